// Base64 decoding for inline binary data in VTK XML files.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace ewa {

// Decodes `text`, ignoring whitespace. Each 4-character group is decoded on its own, so blocks
// encoded separately (VTK encodes the header and the data apart, with '=' padding between)
// decode to their concatenation. Returns false on any other character or an incomplete group.
bool decodeBase64(std::string_view text, std::vector<uint8_t>& out);

}  // namespace ewa
