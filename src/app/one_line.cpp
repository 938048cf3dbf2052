// oneLine: multi-line error text joined into one line.
#include "app/one_line.h"

namespace ewa {

std::string oneLine(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') {
      if (!out.empty() && out.back() != ' ' && out.back() != ':') out += " |";
      out += ' ';
    } else if (c != '\r') {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '|')) out.pop_back();
  return out;
}

}  // namespace ewa
