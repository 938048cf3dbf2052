// The table of the window's keys, and the lookup the input handler dispatches through.
#include "ui/key_bindings.h"

#include <GLFW/glfw3.h>

namespace ewa {

namespace {

constexpr int kCtrl = GLFW_MOD_CONTROL;
constexpr int kShift = GLFW_MOD_SHIFT;

std::vector<KeyBinding> makeKeyBindings() {
  using C = KeyCommand;
  return {
      {GLFW_KEY_X, 0, C::ToggleAxes, "orientation axes on or off",
       "show or hide the orientation axes (bottom right, above the probe line; also the panel's "
       "\"axes\" checkbox; on at first, and kept in the settings)"},
      {GLFW_KEY_M, 0, C::MarkPoint,
       "mark the point under the cursor (the probe gives the distance)",
       "mark the point under the cursor (a yellow ring): the probe line then also gives the "
       "distance from it, in world units, named when the file names them (`mm` for DICOM and most "
       "NIfTI files, `µm` for microscopy); `M` over empty space clears it"},
      {GLFW_KEY_R, 0, C::ResetCamera, "reset the camera", nullptr},
      {GLFW_KEY_C, 0, C::NextChannel, "next channel",
       "a file of several channels (RGB DICOM or TIFF, an OME-TIFF's or ImageJ hyperstack's "
       "channels, a 4D NRRD's colour or vector axis: `--channel`): open the next one in place, "
       "round the end, keeping the camera, the crop and the frame; each channel has its own "
       "transfer function while you page (the one it had when last shown, else the file's for "
       "that channel: its `NAME.cC.tf.json` sidecar, else made from its histogram: stains differ "
       "in range) (also the arrows beside \"channel K of N\" in the panel)"},
      {GLFW_KEY_C, kShift, C::PreviousChannel, "previous channel",
       "open the previous channel in place, as `C` the next"},
      {GLFW_KEY_PAGE_DOWN, 0, C::NextFrame, "next frame of a file of several",
       "a file of several volumes (a 4D NIfTI's or NRRD's time points, an OME-TIFF's or ImageJ "
       "hyperstack's, a DICOM series' diffusion directions, echoes or time points: `--frame`): "
       "open the next one in place, round the end, keeping the camera, the crop and the transfer "
       "function being edited (also the arrows beside \"frame K of N\" under the volume's name in "
       "the panel); presses while a frame loads are counted, not refused: the frame they add up "
       "to opens next"},
      {GLFW_KEY_PAGE_UP, 0, C::PreviousFrame, "previous frame of a file of several",
       "open the previous volume in place, as `Page Down` the next"},
      {GLFW_KEY_1, 0, C::ViewPlusX, "look along +X",
       "look along +X (also the panel's \"look along\" buttons), framing the volume; for a volume "
       "with patient axes the buttons (\"view from\") read R, L, A, P, I, S: the view from the "
       "patient's right, left, anterior, posterior, inferior and superior side (LPS), with "
       "superior up, and anterior up in the axial views"},
      {GLFW_KEY_2, 0, C::ViewMinusX, "look along -X", nullptr},
      {GLFW_KEY_3, 0, C::ViewPlusY, "look along +Y", nullptr},
      {GLFW_KEY_4, 0, C::ViewMinusY, "look along -Y", nullptr},
      {GLFW_KEY_5, 0, C::ViewPlusZ, "look along +Z", nullptr},
      {GLFW_KEY_6, 0, C::ViewMinusZ, "look along -Z", nullptr},
      {GLFW_KEY_F12, 0, C::Screenshot, "screenshot", "screenshot (also the panel's button)"},
      {GLFW_KEY_F1, 0, C::KeysHelp, "this list",
       "show or hide the list of keys (also the panel's \"keys (F1)\")"},
      {GLFW_KEY_O, kCtrl, C::OpenFile,
       "open a volume (or drop a file; a .json: a transfer function)",
       "open a volume (also the panel's \"Open...\" button)"},
      {GLFW_KEY_S, kCtrl, C::SaveVolume, "save the volume (NRRD, NIfTI, MetaImage, TIFF)",
       "save the volume on screen as NRRD, NIfTI, MetaImage (`.mha`, `.mhd`) or TIFF, with its "
       "transfer function beside it (also the panel's \"Save volume...\" button)"},
      {GLFW_KEY_F5, 0, C::Reload, "reload the file",
       "read the volume's file again, keeping the camera, frame, channel and transfer function (a "
       "grid of another size or spacing is framed anew; also the panel's \"Reload\")"},
      {GLFW_KEY_C, kCtrl, C::CopyView, "copy the view as command-line options",
       "copy the view as command-line options (also the panel's \"copy view\" button beside "
       "\"look along\"): `--camera-position=X,Y,Z --camera-focal-point=... "
       "--camera-view-up=... --camera-view-angle=A` (`--camera-orthographic`), "
       "`--resolution=W,H` of the picture, and the crop box and switched-on clipping planes "
       "(`--crop=...`, `--clip-plane=...`), to the clipboard, the panel and stderr; `ewaview FILE "
       "--tf F.tf.json OPTIONS -o view.png` renders the same picture headless"},
      {GLFW_KEY_Z, kCtrl, C::Undo, "undo a transfer-function edit",
       "undo the last transfer-function edit (also the editor's \"Undo\" button)"},
      {GLFW_KEY_Y, kCtrl, C::Redo, "redo a transfer-function edit",
       "redo the last transfer-function edit undone (also the editor's \"Redo\" button)"},
      {GLFW_KEY_Z, kCtrl | kShift, C::Redo, "redo a transfer-function edit", nullptr},
      {GLFW_KEY_Q, 0, C::Quit, "quit", nullptr},
      {GLFW_KEY_ESCAPE, 0, C::Quit, "quit", nullptr},
  };
}

// How much a row's modifiers say: Ctrl+C is a command of its own, Shift+C a variant of C.
int weight(int mods) {
  return ((mods & kCtrl) ? 2 : 0) + ((mods & kShift) ? 1 : 0);
}

std::string keyName(int key) {
  if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9))
    return std::string(1, char(key));  // GLFW's codes of letters and digits are their ASCII
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25) return "F" + std::to_string(key - GLFW_KEY_F1 + 1);
  switch (key) {
    case GLFW_KEY_ESCAPE:
      return "Escape";
    case GLFW_KEY_PAGE_UP:
      return "Page Up";
    case GLFW_KEY_PAGE_DOWN:
      return "Page Down";
    default:
      return "key " + std::to_string(key);
  }
}

}  // namespace

const std::vector<KeyBinding>& keyBindings() {
  static const std::vector<KeyBinding> bindings = makeKeyBindings();
  return bindings;
}

const KeyBinding* keyBindingFor(int key, int mods) {
  const KeyBinding* best = nullptr;
  for (const KeyBinding& b : keyBindings())
    if (b.key == key && (b.mods & ~mods & (kCtrl | kShift)) == 0 &&
        (!best || weight(b.mods) > weight(best->mods)))
      best = &b;
  return best;
}

std::string keyText(const KeyBinding& binding) {
  return std::string((binding.mods & kCtrl) ? "Ctrl+" : "") +
         ((binding.mods & kShift) ? "Shift+" : "") + keyName(binding.key);
}

const std::vector<PointerBinding>& pointerBindings() {
  static const std::vector<PointerBinding> bindings = {
      {"left drag", "orbit about the focal point", nullptr},
      {"right drag, wheel", "zoom", "zoom (dolly)"},
      {"middle drag, Shift+left drag", "pan", nullptr},
      {"double-click", "centre the view on the point under the cursor",
       "centre the view on the point under the cursor and orbit about it (the point the probe "
       "names: it becomes the focal point, in the middle of the view, at the depth it had)"},
      {"drop a file on the window", "open it (a .json: a transfer function)",
       "open it; a `.json` file goes to the transfer-function editor instead: ewaview's transfer "
       "function (as **Load**), else a ParaView preset file (its first map, rescaled, as **Import "
       "ParaView**)"},
  };
  return bindings;
}

}  // namespace ewa
