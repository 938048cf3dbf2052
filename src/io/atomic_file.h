// Writing a whole file so that readers see either the old file or the complete new one.
#pragma once

#include <string>
#include <string_view>

namespace ewa {

// Writes `bytes` to a new temporary file beside `path` (a unique name made by mkstemp, so no
// fixed ".tmp" name can be raced or pre-planted as a link), flushes it to disk, then renames it
// over `path`. On any failure the temporary file is removed and `path` is left as it was.
// Refuses a `path` that is a directory. The new file gets mode 0644 less the process umask.
// Throws std::runtime_error("<path>: cannot write: <reason>").
void writeFileAtomically(const std::string& path, std::string_view bytes);

// True when `a` and `b` name the same existing file (same device and inode), so a writer can
// refuse to replace one of its inputs whatever the spelling of the two paths.
bool sameExistingFile(const std::string& a, const std::string& b);

}  // namespace ewa
