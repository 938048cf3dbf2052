// FileDialog: the open-volume window built from ImGui widgets.
#include "ui/file_dialog.h"

#include <imgui.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

namespace ewa {

namespace fs = std::filesystem;

void FileDialog::open(const std::string& folder) {
  open_ = true;
  justOpened_ = true;
  std::error_code ec;
  const std::string start =
      !folder.empty() && fs::is_directory(folder, ec) ? folder : fs::current_path(ec).string();
  changeFolder(start);
}

void FileDialog::changeFolder(const std::string& folder) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(folder, ec);
  if (ec) canonical = folder;
  try {
    entries_ = listDirectory(canonical.string(),
                             allFiles_ ? std::vector<std::string>{} : volumeFileExtensions());
    folder_ = canonical.string();
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();  // stay in the folder we had
  }
  std::snprintf(pathBuffer_, sizeof pathBuffer_, "%s", folder_.c_str());
  selected_ = -1;
}

std::optional<std::string> FileDialog::draw() {
  if (!open_) return std::nullopt;
  std::optional<std::string> chosen;
  ImGui::SetNextWindowSize(ImVec2(560.0f, 420.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);
  const bool focusPath = justOpened_;
  if (justOpened_) ImGui::SetNextWindowFocus();
  justOpened_ = false;
  if (ImGui::Begin("Open volume", &open_)) {
    if (ImGui::Button("Up")) changeFolder(fs::path(folder_).parent_path().string());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (focusPath) ImGui::SetKeyboardFocusHere();  // type a path at once
    // Enter on a folder goes there; on a file opens it.
    if (ImGui::InputText("##path", pathBuffer_, sizeof pathBuffer_,
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
      std::error_code ec;
      if (fs::is_directory(pathBuffer_, ec))
        changeFolder(pathBuffer_);
      else
        chosen = std::string(pathBuffer_);
    }
    if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error_.c_str());
    const float footer = ImGui::GetFrameHeightWithSpacing() * 1.3f;
    if (ImGui::BeginChild("entries", ImVec2(0.0f, -footer), true)) {
      for (int n = 0; n < int(entries_.size()); ++n) {
        const DirEntry& e = entries_[size_t(n)];
        char label[1100];
        if (e.directory)
          std::snprintf(label, sizeof label, "[dir] %s", e.name.c_str());
        else
          std::snprintf(label, sizeof label, "%s  (%.1f MB)", e.name.c_str(), double(e.size) / 1e6);
        if (ImGui::Selectable(label, selected_ == n, ImGuiSelectableFlags_AllowDoubleClick)) {
          selected_ = n;
          const std::string full = (fs::path(folder_) / e.name).string();
          if (e.directory && ImGui::IsMouseDoubleClicked(0)) {
            changeFolder(full);
            break;  // entries_ changed under the loop
          }
          std::snprintf(pathBuffer_, sizeof pathBuffer_, "%s", full.c_str());
          if (!e.directory && ImGui::IsMouseDoubleClicked(0)) chosen = full;
        }
      }
    }
    ImGui::EndChild();
    if (ImGui::Checkbox("all files", &allFiles_)) changeFolder(folder_);
    ImGui::SameLine();
    ImGui::TextDisabled(allFiles_ ? "(raw files need --raw-* on the command line)"
                                  : "volumes, DICOM, NIfTI, TIFF, SLC");
    // A DICOM series or a TIFF stack is a folder: open the one shown.
    ImGui::SameLine(ImGui::GetWindowWidth() - 240.0f);
    if (ImGui::Button("Open folder")) chosen = folder_;
    ImGui::SameLine();
    if (ImGui::Button("Open")) {
      std::error_code ec;
      if (fs::is_directory(pathBuffer_, ec))
        changeFolder(pathBuffer_);
      else
        chosen = std::string(pathBuffer_);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) open_ = false;
  }
  ImGui::End();
  if (chosen) open_ = false;
  return chosen;
}

}  // namespace ewa
