// The check every writer makes before replacing a file: is it one of the inputs?
#include "io/input_guard.h"

#include <stdexcept>

#include "io/atomic_file.h"

namespace ewa {

void refuseToReplaceInputs(const std::string& output, const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    if (input.empty() || !sameExistingFile(output, input)) continue;
    const std::string named = input == output ? "" : " (" + input + ")";
    throw std::runtime_error(output + ": is an input file" + named + "; refusing to overwrite it");
  }
}

}  // namespace ewa
