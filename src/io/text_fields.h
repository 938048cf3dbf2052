// Strict parsing of the words and numbers found in text headers (no locale, no silent junk).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ewa {

// Without leading and trailing spaces, tabs, carriage returns and newlines.
std::string_view trimView(std::string_view text);
std::string trim(std::string_view text);
// ASCII lowercase.
std::string toLower(std::string_view text);
// Lowercase with all spaces and tabs removed: "Data File" and "datafile" compare equal.
std::string normalizedKey(std::string_view text);
// Splits on any of `separators`, dropping empty pieces.
std::vector<std::string> splitWords(std::string_view text, std::string_view separators = " \t");

// The whole text must be a decimal integer (optional sign) that fits int64; false otherwise.
bool parseInt64(std::string_view text, int64_t& out);
// The whole text must be a number (decimal or exponent form, optional sign, "nan", "inf").
bool parseDouble(std::string_view text, double& out);
// Parses every word of `text` as a number; false if any is not one.
bool parseInt64List(std::string_view text, std::vector<int64_t>& out);
bool parseDoubleList(std::string_view text, std::vector<double>& out);

// Names in natural order: digit runs compare by value ("slice2" before "slice10"; TIFF stacks).
bool naturalLess(const std::string& a, const std::string& b);

}  // namespace ewa
