// LiveTransferFunction: editor edits to GPU tables now, new splat sets from a worker later.
#include "ui/live_transfer_function.h"

#include <filesystem>
#include <optional>

#include "io/transfer_function_io.h"
#include "render/splat_renderer.h"

namespace ewa {

void LiveTransferFunction::reset(const Volume& volume, const TransferFunction& tf,
                                 const std::string& filePath, bool printLayout) {
  dropBuild();
  volume_ = &volume;
  editor_ = std::make_unique<TfEditor>(volume, tf, filePath);
  editor_->setPrintLayout(printLayout);
}

const TransferFunction* LiveTransferFunction::drawAndApply(LodRenderer& lod,
                                                           const Classification& classification) {
  if (!editor_ || !editor_->draw()) return nullptr;
  const TransferFunction& tf = editor_->transferFunction();
  if (SplatRenderer* full = lod.editTransferFunction(tf))
    builder_.request(*volume_, tf, classification, full->maxSplats());
  ++revision_;
  return &tf;
}

void LiveTransferFunction::buildFullLevel(LodRenderer& lod, const Classification& classification) {
  if (!editor_) return;
  lod.prepareFullLevel();  // a new set of renderers has none yet
  const TransferFunction& tf = editor_->transferFunction();
  if (SplatRenderer* full = lod.editTransferFunction(tf))
    builder_.request(*volume_, tf, classification, full->maxSplats());
}

void LiveTransferFunction::buildFullSplats(LodRenderer& lod, const Classification& classification) {
  if (!editor_) return;
  if (SplatRenderer* full = lod.fullSplatRenderer())
    builder_.request(*volume_, editor_->transferFunction(), classification, full->maxSplats());
}

bool LiveTransferFunction::takeBuilt(LodRenderer& lod, std::string* error) {
  try {
    std::optional<BuiltSplats> built = builder_.poll();
    if (built) {
      uploading_ = !lod.beginFullSplats(std::move(built->splats), built->classification);
      return !uploading_;
    }
    if (!uploading_) return false;
    if (lod.takeUploadedFullSplats()) {
      uploading_ = false;
      return true;
    }
    uploading_ = lod.uploadingFullSplats();  // else dropped: another volume or function
    return false;
  } catch (const std::exception& e) {  // too many visible voxels: the old set stays
    uploading_ = false;
    *error = e.what();
  }
  return true;
}

void LiveTransferFunction::dropBuild() {
  uploading_ = false;
  try {
    builder_.finish();
  } catch (const std::exception&) {
    // Its error is about a set nobody will draw.
  }
}

std::string LiveTransferFunction::keep(const std::string& configDir, const std::string& previous,
                                       std::string* error) {
  if (!editor_) return previous;
  if (editor_->editedSinceFile() && !configDir.empty()) {
    const std::string path = (std::filesystem::path(configDir) / "last.tf.json").string();
    std::error_code ec;
    std::filesystem::create_directories(configDir, ec);  // a first run: the folder is not there
    try {
      saveTransferFunction(path, editor_->transferFunction());
      return path;
    } catch (const std::exception& e) {
      *error = e.what();
      return previous;
    }
  }
  if (!editor_->lastFile().empty()) return std::filesystem::absolute(editor_->lastFile()).string();
  return previous;
}

}  // namespace ewa
