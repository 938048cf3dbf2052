// Writing a whole file so that readers see either the old file or the complete new one.
#pragma once

#include <string>
#include <string_view>

namespace ewa {

// Writes `bytes` to a new temporary file beside `path` (a unique name made by mkstemp, so no
// fixed ".tmp" name can be raced or pre-planted as a link), flushes it to disk, then renames it
// over `path`. On any failure the temporary file is removed and `path` is left as it was.
// Refuses a `path` that is a directory, block device or socket; a FIFO or character device
// (`/dev/null`, a pipe, a terminal) or a name of an open file (`/dev/stdout`, `/dev/fd/N`, a
// link into /proc/self/fd) gets `bytes` written straight into it.
// The new file gets mode 0666 less the process umask.
// Throws std::runtime_error("<path>: cannot write: <reason>").
// Creates missing parent folders when `makeParents`.
void writeFileAtomically(const std::string& path, std::string_view bytes, bool makeParents = false);

// For writers that stream a file (videos): creates an empty file with a unique name beside
// `path`, with the mode writeFileAtomically gives, and returns its name; the caller renames it
// over `path` when complete or removes it. Refuses a `path` that exists and is not a regular
// file (renaming over a device would replace it). Throws std::runtime_error("<path>: cannot write:
// ...").
std::string createTemporaryBeside(const std::string& path);

// True when `a` and `b` name the same existing file (same device and inode), so a writer can
// refuse to replace one of its inputs whatever the spelling of the two paths.
bool sameExistingFile(const std::string& a, const std::string& b);

// The whole file as a string; throws std::runtime_error("path: problem").
std::string readTextFile(const std::string& path);

}  // namespace ewa
