// Hand-written XML tag scanner: no dependency, linear time, every index checked, garbage rejected.
#include "io/xml_scanner.h"

#include "io/load_failure.h"

namespace ewa {

namespace {

constexpr size_t kMaxAttributes = 256;

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

bool isNameChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == ':' || c == '-' || c == '.';
}

// Replaces the five predefined entities; anything else (numeric references) is kept as is.
std::string decodeEntities(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  static const std::pair<std::string_view, char> kEntities[] = {
      {"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'}, {"&apos;", '\''}};
  for (size_t i = 0; i < raw.size(); ++i) {
    bool replaced = false;
    if (raw[i] == '&') {
      for (const auto& [entity, c] : kEntities) {
        if (raw.substr(i, entity.size()) == entity) {
          out.push_back(c);
          i += entity.size() - 1;
          replaced = true;
          break;
        }
      }
    }
    if (!replaced) out.push_back(raw[i]);
  }
  return out;
}

}  // namespace

const std::string* XmlTag::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

void XmlScanner::fail(const std::string& problem) const {
  failLoad(path_, "malformed XML at byte " + std::to_string(pos_) + ": " + problem);
}

size_t XmlScanner::skipSpace(size_t i) const {
  while (i < text_.size() && isSpace(text_[i])) ++i;
  return i;
}

size_t XmlScanner::scanName(size_t i) const {
  while (i < text_.size() && isNameChar(text_[i])) ++i;
  return i;
}

bool XmlScanner::next(XmlTag& tag) {
  while (true) {
    const size_t lt = text_.find('<', pos_);
    if (lt == std::string_view::npos) {
      pos_ = text_.size();
      return false;
    }
    pos_ = lt;
    const std::string_view rest = text_.substr(lt);
    // Markup that is not a tag: skip to its terminator.
    const std::pair<std::string_view, std::string_view> kSkipped[] = {
        {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}, {"<!", ">"}};
    bool skipped = false;
    for (const auto& [open, close] : kSkipped) {
      if (rest.substr(0, open.size()) == open) {
        const size_t end = text_.find(close, lt + open.size());
        if (end == std::string_view::npos) fail("unterminated " + std::string(open));
        pos_ = end + close.size();
        skipped = true;
        break;
      }
    }
    if (!skipped) break;
  }

  tag = XmlTag();
  tag.begin = pos_;
  size_t i = pos_ + 1;
  if (i < text_.size() && text_[i] == '/') {
    tag.closing = true;
    ++i;
  }
  const size_t nameEnd = scanName(i);
  if (nameEnd == i) fail("expected a tag name after '<'");
  tag.name.assign(text_.substr(i, nameEnd - i));
  i = nameEnd;
  while (true) {
    i = skipSpace(i);
    if (i >= text_.size()) fail("unterminated tag <" + tag.name);
    if (text_[i] == '>') {
      ++i;
      break;
    }
    if (text_[i] == '/' && i + 1 < text_.size() && text_[i + 1] == '>' && !tag.closing) {
      tag.selfClosing = true;
      i += 2;
      break;
    }
    if (tag.closing) fail("unexpected text in closing tag </" + tag.name);
    const size_t keyEnd = scanName(i);
    if (keyEnd == i) fail("bad attribute syntax in <" + tag.name);
    std::string key(text_.substr(i, keyEnd - i));
    i = skipSpace(keyEnd);
    if (i >= text_.size() || text_[i] != '=') fail("attribute " + key + " has no value");
    i = skipSpace(i + 1);
    if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) {
      fail("attribute " + key + " value is not quoted");
    }
    const size_t close = text_.find(text_[i], i + 1);
    if (close == std::string_view::npos) fail("unterminated value of attribute " + key);
    if (tag.attributes.size() >= kMaxAttributes) fail("too many attributes in <" + tag.name);
    tag.attributes.emplace_back(std::move(key), decodeEntities(text_.substr(i + 1, close - i - 1)));
    i = close + 1;
  }
  tag.end = i;
  pos_ = i;
  return true;
}

}  // namespace ewa
