// writeFileAtomically: replace a file's contents through a temporary file and a rename.
#pragma once

#include <string>

namespace ewa {

// Writes `contents` to "path.tmp" beside `path`, then renames it over `path`, so readers see
// the old file or the new one, never half of one. Creates missing parent folders when
// `makeParents`. Throws std::runtime_error("path: problem").
void writeFileAtomically(const std::string& path, const std::string& contents,
                         bool makeParents = false);

// The whole file as a string; throws std::runtime_error("path: problem").
std::string readTextFile(const std::string& path);

}  // namespace ewa
