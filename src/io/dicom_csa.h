// Siemens CSA headers (private tags (0029,xx10) and (0029,xx20)): the named values they hold.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ewa {

// The items of the element named `name` in the CSA header `data` (`size` bytes), in the "SV10"
// format of syngo MR (CSA2; as nibabel and dcm2niix read it): "SV10", four bytes, the element
// count and a check word, then each element's 64-byte name, VM, VR, SyngoDT, item count and
// check word, each item four int32 (the second its length) and its text, padded to 4 bytes.
// Items are trimmed of padding; empty items end the list. Empty when the element is absent or
// the header is not SV10 or runs past its bytes (counts and lengths are checked against them).
std::vector<std::string> csaValues(const uint8_t* data, size_t size, const std::string& name);

}  // namespace ewa
