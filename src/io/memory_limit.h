// The sanity bound for buffers whose size comes from a file header: the machine's physical memory.
#pragma once

#include <cstdint>
#include <string>

namespace ewa {

// Physical memory in bytes (sysconf), or a large fallback when the system will not say.
uint64_t physicalMemoryBytes();
// Throws LoadError("<path>: <what> of N bytes is more than this machine's memory") when
// `bytes` exceeds physicalMemoryBytes() or does not fit size_t.
void checkAllocation(const std::string& path, uint64_t bytes, const std::string& what);

}  // namespace ewa
