// Base64 decoding, group by group, tolerant of whitespace and of padded blocks back to back.
#include "io/base64.h"

namespace ewa {

namespace {

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  if (c == '=') return -2;  // padding
  return -1;
}

}  // namespace

bool decodeBase64(std::string_view text, std::vector<uint8_t>& out) {
  out.clear();
  out.reserve(text.size() / 4 * 3);
  int group[4];
  int have = 0;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
    const int v = sextet(c);
    if (v == -1) return false;
    group[have++] = v;
    if (have < 4) continue;
    have = 0;
    // Padding may only end a group: "xx==" gives 1 byte, "xxx=" gives 2.
    if (group[0] < 0 || group[1] < 0 || (group[2] < 0 && group[3] >= 0)) return false;
    const uint32_t bits = (uint32_t(group[0]) << 18) | (uint32_t(group[1]) << 12) |
                          (uint32_t(group[2] < 0 ? 0 : group[2]) << 6) |
                          uint32_t(group[3] < 0 ? 0 : group[3]);
    out.push_back(static_cast<uint8_t>(bits >> 16));
    if (group[2] >= 0) out.push_back(static_cast<uint8_t>(bits >> 8));
    if (group[3] >= 0) out.push_back(static_cast<uint8_t>(bits));
  }
  return have == 0;
}

}  // namespace ewa
