// The window's keys and mouse, listed in a window of their own (F1, the panel's "keys").
#pragma once

namespace ewa {

// Draws the list while `*open` (its close button clears it).
void drawKeysHelp(bool* open);

}  // namespace ewa
