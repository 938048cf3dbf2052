// Data written as text: numbers (ASCII NRRD, legacy VTK) and hex digits (hex NRRD).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ewa {

// `count` numbers from `offset` in the file at `path`, separated by white space or commas.
// The count is checked against the file's size before anything is allocated. Throws
// LoadError("<path>: <what> ...") when the file holds fewer numbers or a word is not one.
std::vector<double> readTextNumbers(const std::string& path, uint64_t offset, uint64_t count,
                                    const std::string& what);
// The same for text already in memory (an XML element's content); `path` names it in errors.
std::vector<double> parseTextNumbers(const std::string& path, std::string_view text, uint64_t count,
                                     const std::string& what);

// `v` as text that reads back as the same double ("%.17g"): what the writers put in headers.
std::string roundTripText(double v);
// `v` to six significant digits ("%g"): for messages and notes.
std::string shortText(double v);

// `count` bytes written as pairs of hex digits (white space anywhere) from `offset`.
std::vector<uint8_t> readHexBytes(const std::string& path, uint64_t offset, uint64_t count,
                                  const std::string& what);

}  // namespace ewa
