// Refusing to write over a file a volume was read from (--output, --save-volume, the window's
// saves): an output that names an input would destroy the data it shows.
#pragma once

#include <string>
#include <vector>

namespace ewa {

// Throws std::runtime_error("<output>: is an input file (<input>); refusing to overwrite it") when
// `output` names the same existing file as one of `inputs`, however either is spelled (links,
// relative paths, hard links: same device and inode).
void refuseToReplaceInputs(const std::string& output, const std::vector<std::string>& inputs);

}  // namespace ewa
