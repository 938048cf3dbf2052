// FileDialog: the open-volume and save-volume window built from ImGui widgets.
#include "ui/file_dialog.h"

#include <imgui.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io/volume_writer.h"

namespace ewa {

namespace fs = std::filesystem;

void FileDialog::open(const std::string& folder, Purpose purpose, const std::string& fileName,
                      const std::string& optionLabel) {
  open_ = true;
  optionLabel_ = optionLabel;
  optionChecked_ = true;
  justOpened_ = true;
  purpose_ = purpose;
  replacing_.clear();
  std::error_code ec;
  const std::string start =
      !folder.empty() && fs::is_directory(folder, ec) ? folder : fs::current_path(ec).string();
  changeFolder(start);
  if (purpose_ == Purpose::SaveVolume && !fileName.empty())
    std::snprintf(pathBuffer_, sizeof pathBuffer_, "%s",
                  (fs::path(folder_) / fileName).string().c_str());
}

void FileDialog::changeFolder(const std::string& folder) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(folder, ec);
  if (ec) canonical = folder;
  try {
    const std::vector<std::string> kinds =
        purpose_ == Purpose::SaveVolume ? savedVolumeExtensions() : volumeFileExtensions();
    entries_ = listDirectory(canonical.string(), allFiles_ ? std::vector<std::string>{} : kinds,
                             false, purpose_ != Purpose::SaveVolume);
    folder_ = canonical.string();
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();  // stay in the folder we had
  }
  std::snprintf(pathBuffer_, sizeof pathBuffer_, "%s", folder_.c_str());
  selected_ = -1;
}

std::optional<std::string> FileDialog::accept() {
  error_.clear();
  std::error_code ec;
  fs::path path(pathBuffer_);
  if (path.is_relative()) path = fs::path(folder_) / path;  // a name typed in the folder shown
  if (fs::is_directory(path, ec)) {
    changeFolder(path.string());
    return std::nullopt;
  }
  if (purpose_ == Purpose::Open) return path.string();
  if (path.extension().empty()) path += ".nrrd";
  if (!savedVolumeFormat(path.string())) {
    error_ = "volumes are saved as NRRD, NIfTI, MetaImage or TIFF: name the file NAME" +
             savedVolumeExtensionsText();
    return std::nullopt;
  }
  if (!fs::is_directory(path.parent_path(), ec)) {
    error_ = "no such folder: " + path.parent_path().string();
    return std::nullopt;
  }
  // A MetaImage header (.mhd) replaces the data file it names too.
  std::vector<std::string> existing;
  if (fs::exists(path, ec)) existing.push_back(path.filename().string());
  if (savedVolumeFormat(path.string()) == SavedVolumeFormat::MetaImageHeader) {
    const fs::path data = metaImageDataFileOf(path.string());
    if (fs::exists(data, ec)) existing.push_back(data.filename().string());
  }
  if (!existing.empty()) {
    replacing_ = path.string();
    replacingText_ = existing.size() == 1 ? existing[0] + " exists."
                                          : existing[0] + " and " + existing[1] + " exist.";
    askReplace_ = true;  // the popup opens at the window's level, not inside the list
    return std::nullopt;
  }
  return path.string();
}

std::optional<std::string> FileDialog::drawReplacePrompt() {
  std::optional<std::string> chosen;
  if (askReplace_) ImGui::OpenPopup("Replace file?");
  askReplace_ = false;
  if (ImGui::BeginPopupModal("Replace file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted(replacingText_.c_str());
    if (ImGui::Button("Replace")) {
      chosen = replacing_;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return chosen;
}

std::optional<std::string> FileDialog::draw() {
  if (!open_) return std::nullopt;
  const bool saving = purpose_ == Purpose::SaveVolume;
  std::optional<std::string> chosen;
  ImGui::SetNextWindowSize(ImVec2(560.0f, 420.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);
  const bool focusPath = justOpened_;
  if (justOpened_) ImGui::SetNextWindowFocus();
  justOpened_ = false;
  // One window (one place on screen) under either title.
  if (ImGui::Begin(saving ? "Save volume###files" : "Open volume###files", &open_)) {
    if (ImGui::Button("Up")) changeFolder(fs::path(folder_).parent_path().string());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (focusPath) ImGui::SetKeyboardFocusHere();  // type a path at once
    // Enter on a folder goes there; on a file chooses it.
    if (ImGui::InputText("##path", pathBuffer_, sizeof pathBuffer_,
                         ImGuiInputTextFlags_EnterReturnsTrue))
      chosen = accept();
    if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error_.c_str());
    const float footer = ImGui::GetFrameHeightWithSpacing() * (optionLabel_.empty() ? 1.3f : 2.3f);
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
          if (!e.directory && ImGui::IsMouseDoubleClicked(0)) chosen = accept();
        }
      }
    }
    ImGui::EndChild();
    if (!optionLabel_.empty()) ImGui::Checkbox(optionLabel_.c_str(), &optionChecked_);
    if (ImGui::Checkbox("all files", &allFiles_)) changeFolder(folder_);
    ImGui::SameLine();
    if (saving)
      ImGui::TextDisabled(".nrrd .nii(.gz) .mha .mhd .tif + NAME.tf.json");
    else
      ImGui::TextDisabled(allFiles_ ? "(raw files need --raw-* on the command line)"
                                    : "volumes, DICOM, NIfTI, TIFF, SLC");
    ImGui::SameLine(ImGui::GetWindowWidth() - (saving ? 130.0f : 240.0f));
    // A DICOM series or a TIFF stack is a folder: open the one shown.
    if (!saving && ImGui::Button("Open folder")) chosen = folder_;
    if (!saving) ImGui::SameLine();
    if (ImGui::Button(saving ? "Save" : "Open")) chosen = accept();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) open_ = false;
    if (const auto replace = drawReplacePrompt()) chosen = replace;
  }
  ImGui::End();
  if (chosen) open_ = false;
  return chosen;
}

}  // namespace ewa
