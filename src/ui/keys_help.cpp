// The keys window: one table of what each key and mouse action does, as the README lists them.
#include "ui/keys_help.h"

#include <imgui.h>

namespace ewa {

namespace {

struct KeyLine {
  const char* keys;
  const char* does;
};

constexpr KeyLine kLines[] = {
    {"left drag", "orbit about the focal point"},
    {"right drag, wheel", "zoom"},
    {"middle drag, Shift+left drag", "pan"},
    {"double-click", "centre the view on the point under the cursor"},
    {"M", "mark the point under the cursor (the probe gives the distance)"},
    {"R", "reset the camera"},
    {"1 ... 6", "look along +X, -X, +Y, -Y, +Z, -Z"},
    {"X", "orientation axes on or off"},
    {"Page Down, Page Up", "next, previous frame of a file of several"},
    {"C, Shift+C", "next, previous channel"},
    {"Ctrl+Z, Ctrl+Y", "undo, redo a transfer-function edit"},
    {"Ctrl+C", "copy the view as command-line options"},
    {"Ctrl+O", "open a volume (or drop a file; a .json: a transfer function)"},
    {"Ctrl+S", "save the volume (NRRD, NIfTI, MetaImage)"},
    {"F5", "reload the file"},
    {"F12", "screenshot"},
    {"F1", "this list"},
    {"Q, Escape", "quit"},
};

}  // namespace

void drawKeysHelp(bool* open) {
  if (!*open) return;
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Keys", open, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      for (const KeyLine& line : kLines) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(line.keys);
        ImGui::TableSetColumnIndex(1);
        ImGui::TextUnformatted(line.does);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace ewa
