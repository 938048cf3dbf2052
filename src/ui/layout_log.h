// LayoutLog: the window test's record of where panel items are (EWAVIEW_PRINT_LAYOUT).
#pragma once

#include <imgui.h>

#include <cstdio>
#include <map>
#include <string>

namespace ewa {

// Prints "NAME X Y W H" for ImGui's last item on stdout when on, whenever its place differs
// from the one last printed for NAME (a panel scrolled moves it), so a script's last line for
// NAME is where the item is.
class LayoutLog {
 public:
  void setOn(bool on) { on_ = on; }
  // Prints every item again from the next frame (a new volume: its lines mark it ready).
  void forget() { printed_.clear(); }
  void lastItem(const std::string& name) {
    if (on_) print(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  }
  // The current window's place and size (call between its Begin and End).
  void window(const std::string& name) {
    if (!on_) return;
    const ImVec2 a = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    print(name, a, ImVec2(a.x + size.x, a.y + size.y));
  }

 private:
  void print(const std::string& name, ImVec2 a, ImVec2 b) {
    char line[160];
    std::snprintf(line, sizeof line, "%s %.0f %.0f %.0f %.0f", name.c_str(), a.x, a.y, b.x - a.x,
                  b.y - a.y);
    std::string& last = printed_[name];
    if (last == line) return;
    last = line;
    std::printf("%s\n", line);
    std::fflush(stdout);
  }

  bool on_ = false;
  std::map<std::string, std::string> printed_;  // the last line printed for each name
};

}  // namespace ewa
