// Strict number and word parsing for header text; uses from_chars so the locale cannot interfere.
#include "io/text_fields.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <system_error>

namespace ewa {

namespace {
bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// from_chars rejects a leading '+', which headers do write.
std::string_view dropPlus(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  return text;
}
}  // namespace

std::string_view trimView(std::string_view text) {
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return text;
}

std::string trim(std::string_view text) {
  return std::string(trimView(text));
}

std::string toLower(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

std::string normalizedKey(std::string_view text) {
  std::string out;
  for (char c : toLower(text)) {
    if (c != ' ' && c != '\t') out.push_back(c);
  }
  return out;
}

std::vector<std::string> splitWords(std::string_view text, std::string_view separators) {
  std::vector<std::string> words;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find_first_of(separators, start);
    const size_t stop = end == std::string_view::npos ? text.size() : end;
    if (stop > start) words.emplace_back(text.substr(start, stop - start));
    start = stop + 1;
  }
  return words;
}

bool parseInt64(std::string_view text, int64_t& out) {
  text = dropPlus(trimView(text));
  if (text.empty()) return false;
  int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return false;
  out = value;
  return true;
}

bool parseDouble(std::string_view text, double& out) {
  text = dropPlus(trimView(text));
  if (text.empty()) return false;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  // Out of range (1e999, also extreme underflow) is an error rather than a silent inf or 0.
  if (ec != std::errc() || end != text.data() + text.size()) return false;
  out = value;
  return true;
}

bool parseInt64List(std::string_view text, std::vector<int64_t>& out) {
  out.clear();
  for (const std::string& word : splitWords(text, " \t\r\n")) {
    int64_t v = 0;
    if (!parseInt64(word, v)) return false;
    out.push_back(v);
  }
  return true;
}

bool parseDoubleList(std::string_view text, std::vector<double>& out) {
  out.clear();
  for (const std::string& word : splitWords(text, " \t\r\n")) {
    double v = 0.0;
    if (!parseDouble(word, v)) return false;
    out.push_back(v);
  }
  return true;
}

bool naturalLess(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(uint8_t(a[i])) && std::isdigit(uint8_t(b[j]))) {
      size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(uint8_t(a[ie]))) ++ie;
      while (je < b.size() && std::isdigit(uint8_t(b[je]))) ++je;
      std::string na = a.substr(i, ie - i), nb = b.substr(j, je - j);
      na.erase(0, std::min(na.find_first_not_of('0'), na.size()));
      nb.erase(0, std::min(nb.find_first_not_of('0'), nb.size()));
      if (na.size() != nb.size()) return na.size() < nb.size();
      if (na != nb) return na < nb;
      i = ie, j = je;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

}  // namespace ewa
