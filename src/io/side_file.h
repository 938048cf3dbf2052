// Reading the small text files that go beside a volume (transfer functions, bookmarks,
// settings, colour-map presets): regular files only, and no bigger than such a file can be.
#pragma once

#include <cstdint>
#include <exception>
#include <string>

namespace ewa {

// The largest side file read: far above any real transfer function, preset list or settings
// file (kilobytes to a few megabytes), far below what would exhaust memory.
constexpr uint64_t kMaxSideFileBytes = 64ull << 20;

// The whole file as a string. Refuses, with std::runtime_error("<path>: <problem>") naming
// `what` ("transfer-function file"), a folder, a FIFO, a device or anything else that is not
// a regular file (opened without blocking, so a FIFO with no writer cannot hang the reader),
// and a file over `maxBytes`.
std::string readSideFile(const std::string& path, const std::string& what,
                         uint64_t maxBytes = kMaxSideFileBytes);

// An exception's message as one line for "<file>: <problem>": nlohmann's tag
// ("[json.exception.out_of_range.403] ") dropped, std::bad_alloc said in words.
std::string problemText(const std::exception& e);

}  // namespace ewa
