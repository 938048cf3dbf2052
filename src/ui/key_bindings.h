// The window's keys, in one table: it drives the input handler (window_input.cpp), the keys
// window (keys_help.cpp) and docs/user/keys.md (ewaview-docs), so the three cannot differ.
#pragma once

#include <string>
#include <vector>

namespace ewa {

// What a key (or a double-click) asks for. The viewer carries out the commands; the input
// handler itself the last two. New values go at the end: the window test logs the numbers.
enum class KeyCommand {
  Screenshot,
  OpenFile,
  SaveVolume,  // Ctrl+S: the volume on screen as NRRD
  Undo,        // Ctrl+Z: the last transfer-function edit
  Redo,        // Ctrl+Y, Ctrl+Shift+Z
  CopyView,    // Ctrl+C: the view as command-line options, to the clipboard
  Reload,      // F5: the volume's file read again, keeping the view
  KeysHelp,    // F1: the list of keys
  ViewPlusX,   // the six views in the order of keys 1..6 (the viewer counts on it)
  ViewMinusX,
  ViewPlusY,
  ViewMinusY,
  ViewPlusZ,
  ViewMinusZ,
  CentreOnCursor,
  MarkPoint,
  ToggleAxes,
  NextFrame,  // Page Down: the file's next volume (4D NIfTI, DICOM volumes at one place)
  PreviousFrame,
  NextChannel,  // C: the file's next channel (RGB, OME-TIFF channels); Shift+C the previous
  PreviousChannel,
  ResetCamera,  // R (the input handler resets the camera itself)
  Quit          // Q, Escape (the input handler closes the window)
};

struct KeyBinding {
  int key;   // GLFW_KEY_*
  int mods;  // GLFW_MOD_CONTROL and GLFW_MOD_SHIFT the key needs; other keys held are ignored
  KeyCommand command;
  const char* does;     // one line, for the keys window
  const char* details;  // the page's words, where it says more; else null
};

// Every key, in the order the keys window and the page list them.
const std::vector<KeyBinding>& keyBindings();
// The binding a press of `key` with `mods` (GLFW_MOD_*) held triggers: of the rows of that key
// whose modifiers are all held, the one needing most (Ctrl over Shift); null for none.
const KeyBinding* keyBindingFor(int key, int mods);
// "Ctrl+Shift+Z", "Page Down", "F1".
std::string keyText(const KeyBinding& binding);

// Mouse input and dropped files, for the keys window and the page (the handler's own code).
struct PointerBinding {
  const char* input;
  const char* does;
  const char* details;  // or null
};
const std::vector<PointerBinding>& pointerBindings();

}  // namespace ewa
