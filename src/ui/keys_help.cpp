// The keys window: what each key and mouse action does, from the key table (key_bindings.cpp).
#include "ui/keys_help.h"

#include <imgui.h>

#include <string>

#include "ui/key_bindings.h"

namespace ewa {

void drawKeysHelp(bool* open) {
  if (!*open) return;
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Keys", open, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      auto row = [](const std::string& input, const char* does) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(input.c_str());
        ImGui::TableSetColumnIndex(1);
        ImGui::TextUnformatted(does);
      };
      for (const PointerBinding& p : pointerBindings()) row(p.input, p.does);
      for (const KeyBinding& k : keyBindings()) row(keyText(k), k.does);
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace ewa
