// docs/user/keys.md, written from the key table (ewaview-docs writes it; a test compares).
#pragma once

#include <string>

namespace ewa {

// The page: the mouse, then every key, with the longer words where the table has them.
std::string keysMarkdown();

}  // namespace ewa
