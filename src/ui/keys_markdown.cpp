// docs/user/keys.md from the key table: the page is generated, never edited by hand.
#include "ui/keys_markdown.h"

#include <sstream>

#include "ui/key_bindings.h"

namespace ewa {

std::string keysMarkdown() {
  std::ostringstream out;
  out << "# The window's keys and mouse\n\n"
      << "<!-- Generated from src/ui/key_bindings.cpp by `build/ewaview-docs docs/user`: edit "
         "the table, not this page. -->\n\n"
      << "The mouse acts on the picture where the cursor is not over a panel; the keys act "
         "unless a panel's text field has the keyboard. `F1` shows this list in the window.\n\n"
      << "| input | does |\n| --- | --- |\n";
  for (const PointerBinding& p : pointerBindings())
    out << "| " << p.input << " | " << (p.details ? p.details : p.does) << " |\n";
  for (const KeyBinding& k : keyBindings())
    out << "| `" << keyText(k) << "` | " << (k.details ? k.details : k.does) << " |\n";
  return out.str();
}

}  // namespace ewa
