// The sanity bound for buffers whose size comes from a file header: the machine's physical memory.
#pragma once

#include <cstdint>
#include <string>

namespace ewa {

// Physical memory in bytes (sysconf), or a large fallback when the system will not say.
uint64_t physicalMemoryBytes();
// The memory this process may use: physical memory, or less where a limit on the address space
// or the data segment is set (ulimit -v, prlimit --as, a batch system's limit).
uint64_t usableMemoryBytes();
// Throws LoadError("<path>: <what> of N bytes is more than this machine's memory") when
// `bytes` exceeds usableMemoryBytes() or does not fit size_t.
void checkAllocation(const std::string& path, uint64_t bytes, const std::string& what);

}  // namespace ewa
