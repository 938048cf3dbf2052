// A small, bounds-checked scanner of XML tags and attributes: enough for VTK .vti headers.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ewa {

struct XmlTag {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // values with entities decoded
  bool closing = false;                                         // </name>
  bool selfClosing = false;                                     // <name ... />
  size_t begin = 0;                                             // offset of '<'
  size_t end = 0;                                               // offset just past '>'

  // Value of attribute `key`, or null when absent.
  const std::string* attribute(std::string_view key) const;
};

// Walks the tags of `text` in order, skipping character data, comments, processing
// instructions, CDATA sections and DOCTYPE. It does not check nesting; callers track what they
// need. Malformed markup throws LoadError("<path>: ..."); it never reads out of bounds.
class XmlScanner {
 public:
  XmlScanner(std::string path, std::string_view text) : path_(std::move(path)), text_(text) {}

  // Fills `tag` with the next tag and returns true, or returns false at the end of the text.
  bool next(XmlTag& tag);

 private:
  [[noreturn]] void fail(const std::string& problem) const;
  size_t skipSpace(size_t i) const;
  size_t scanName(size_t i) const;  // end of an XML name starting at i (i if none)

  std::string path_;
  std::string_view text_;
  size_t pos_ = 0;
};

}  // namespace ewa
