// One-line LoadError messages: sanitizing and quoting text taken from untrusted files.
#include "io/load_failure.h"

namespace ewa {

std::string oneLine(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) c = ' ';
  }
  return out;
}

std::string quoteText(std::string_view text, size_t maxChars) {
  if (text.size() > maxChars) return "'" + oneLine(text.substr(0, maxChars)) + "...'";
  return "'" + oneLine(text) + "'";
}

void failLoad(const std::string& path, const std::string& problem) {
  throw LoadError(oneLine(path + ": " + problem));
}

}  // namespace ewa
