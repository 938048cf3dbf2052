// oneLine: an error message as the single line the command line and Python report.
#pragma once

#include <string>

namespace ewa {

// Line breaks (GL compile logs come with several) become " | "; trailing blanks go.
std::string oneLine(const std::string& text);

}  // namespace ewa
