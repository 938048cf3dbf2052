// Python keyword options -> ewaview::Options through the command line's own parser.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "app/options.h"

namespace ewa::python {

// A usage error, raised in Python as ValueError with the command line's message.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Options that only make sense when a scene is made: the volume and how to read it.
bool isLoadOption(const std::string& key);

// The command-line words for keyword options: render_mode="mip" -> "--render-mode", "mip";
// True -> the bare flag; False or None -> nothing; a sequence -> "a,b,c". Throws UsageError
// for keys the module does not take as options (output, turntable, info, help, ...).
std::vector<std::string> optionWords(const pybind11::dict& options);

// Parses `words` (after the program name) with parseCommandLine, so every option, check and
// message is the command line's. Throws UsageError with the message it prints (one line,
// without the "ewaview: " prefix and the "(see --help)" hint).
Options parseOptionWords(const std::vector<std::string>& words);

}  // namespace ewa::python
