// Numbers and hex bytes read from text data, bounded by the text before anything is allocated.
#include "io/text_numbers.h"

#include <cstdio>
#include <cstdlib>

#include "io/file_bytes.h"
#include "io/load_failure.h"
#include "io/memory_limit.h"

namespace ewa {

namespace {

// Fails unless `bytes` of text can hold `count` items of at least `minChars` characters each
// (separators included but the last).
void checkRoom(const std::string& path, uint64_t bytes, uint64_t count, uint64_t minChars,
               const std::string& what) {
  if (count > (bytes + 1) / minChars)
    failLoad(path, what + " cannot hold " + std::to_string(count) + " values in its " +
                       std::to_string(bytes) + " bytes (truncated file or wrong sizes?)");
}

// The text from `offset` to the end of the file, NUL-terminated, once checkRoom passed.
std::vector<uint8_t> readText(const std::string& path, uint64_t offset, uint64_t count,
                              uint64_t minChars, const std::string& what) {
  const uint64_t size = regularFileSize(path);
  const uint64_t left = offset < size ? size - offset : 0;
  checkRoom(path, left, count, minChars, what);
  std::vector<uint8_t> text = readFileRange(path, offset, left, what);
  text.push_back(0);
  return text;
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// `count` numbers from NUL-terminated text that checkRoom found room for.
std::vector<double> parseNumbers(const std::string& path, const char* p, uint64_t count,
                                 const std::string& what) {
  checkAllocation(path, count * sizeof(double), what + " as numbers");  // count <= text size
  std::vector<double> values(static_cast<size_t>(count));
  for (size_t i = 0; i < values.size(); ++i) {
    while (isSpace(*p) || *p == ',') ++p;
    char* end = nullptr;
    values[i] = std::strtod(p, &end);
    if (end == p)
      failLoad(path, what + " has " + std::to_string(i) + " numbers, not " + std::to_string(count) +
                         " (truncated file or not a number)");
    p = end;
  }
  return values;
}

}  // namespace

std::vector<double> readTextNumbers(const std::string& path, uint64_t offset, uint64_t count,
                                    const std::string& what) {
  const std::vector<uint8_t> text = readText(path, offset, count, 2, what);
  return parseNumbers(path, reinterpret_cast<const char*>(text.data()), count, what);
}

std::vector<double> parseTextNumbers(const std::string& path, std::string_view text, uint64_t count,
                                     const std::string& what) {
  checkRoom(path, text.size(), count, 2, what);
  const std::string terminated(text);  // strtod needs the NUL
  return parseNumbers(path, terminated.c_str(), count, what);
}

std::vector<uint8_t> readHexBytes(const std::string& path, uint64_t offset, uint64_t count,
                                  const std::string& what) {
  const std::vector<uint8_t> text = readText(path, offset, count, 2, what);
  std::vector<uint8_t> bytes(static_cast<size_t>(count));
  size_t at = 0;
  for (size_t i = 0; i < bytes.size(); ++i) {
    int byte = 0;
    for (int half = 0; half < 2; ++half) {
      while (isSpace(char(text[at]))) ++at;
      const int d = hexDigit(char(text[at]));
      if (d < 0) {
        if (text[at] == 0 && at + 1 == text.size())
          failLoad(path, what + " ends after " + std::to_string(i) + " of " +
                             std::to_string(count) + " bytes (truncated file or wrong sizes?)");
        failLoad(path, what + " has a character that is not a hex digit at byte " +
                           std::to_string(at) + " of the data");
      }
      byte = byte * 16 + d;
      ++at;
    }
    bytes[i] = uint8_t(byte);
  }
  return bytes;
}

std::string roundTripText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string shortText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace ewa
