// csaValues: one element's items from a Siemens CSA header (SV10), every count bounded.
#include "io/dicom_csa.h"

#include <algorithm>
#include <cstring>

#include "io/byte_order.h"

namespace ewa {

namespace {

// More elements or items than any scanner writes (nibabel stops at 1000 too): a broken header.
constexpr uint64_t kMaxCsaCount = 1000;

std::string trimmed(const uint8_t* p, size_t n) {
  size_t end = 0;
  while (end < n && p[end] != 0) ++end;  // C strings: the text ends at its first NUL
  std::string text(reinterpret_cast<const char*>(p), end);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  while (!text.empty() && text.front() == ' ') text.erase(text.begin());
  return text;
}

}  // namespace

std::vector<std::string> csaValues(const uint8_t* data, size_t size, const std::string& name) {
  if (size < 16 || std::memcmp(data, "SV10", 4) != 0) return {};
  size_t pos = 8;
  const uint64_t elements = readUnsigned(data + pos, 4, false);
  pos += 8;  // the count and a check word
  if (elements == 0 || elements > kMaxCsaCount) return {};
  for (uint64_t e = 0; e < elements; ++e) {
    // name[64], vm, vr[4], syngodt, item count, check word
    if (size - pos < 84) return {};
    const std::string elementName = trimmed(data + pos, 64);
    const uint64_t items = readUnsigned(data + pos + 76, 4, false);
    pos += 84;
    if (items > kMaxCsaCount) return {};
    std::vector<std::string> values;
    bool ended = false;
    for (uint64_t i = 0; i < items; ++i) {
      if (size - pos < 16) return {};
      const uint64_t length = readUnsigned(data + pos + 4, 4, false);
      pos += 16;
      if (length > size - pos) return {};
      if (length == 0) ended = true;
      if (!ended) values.push_back(trimmed(data + pos, size_t(length)));
      pos += size_t(length);
      pos = std::min(size, pos + size_t((4 - length % 4) % 4));  // a last item may go unpadded
    }
    if (elementName == name) return values;
  }
  return {};
}

}  // namespace ewa
