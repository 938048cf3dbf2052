// docs/user/options.md, written from the option table (ewaview-docs writes it; a test compares).
#pragma once

#include <string>

namespace ewa {

// The page: one section per group, a table of name | value | default | meaning, and each
// option's long help below its group's table.
std::string optionsMarkdown();

}  // namespace ewa
