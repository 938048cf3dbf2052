// LiveTransferFunction: the editor window joined to the renderers: edits show in the next
// frame, the full level's new splat set is built on a worker thread.
#pragma once

#include <memory>
#include <string>

#include "core/async_splat_builder.h"
#include "core/splat_attributes.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "render/lod_renderer.h"
#include "ui/tf_editor.h"

namespace ewa {

class LiveTransferFunction {
 public:
  // A new volume: a new editor (it holds the histogram). Waits for a build of the old volume
  // first, since it reads that volume. `volume` must outlive the next reset() or this object.
  void reset(const Volume& volume, const TransferFunction& tf, const std::string& filePath,
             bool printLayout);
  // Draws the editor; on an edit the levels get the new function (coarse levels classify
  // again, the full splat level only takes the new table) and a worker builds the full
  // level's set. Returns the edited function, or nullptr when nothing changed.
  const TransferFunction* drawAndApply(LodRenderer& lod, const Classification& classification);
  // A new volume on screen: the full splat level gets the editor's function now and a worker
  // builds its splats, so that no frame classifies the full volume itself.
  void buildFullLevel(LodRenderer& lod, const Classification& classification);
  // The full splat level's set for another classification (gradients, surface splats), built
  // on the worker; the levels keep their functions.
  void buildFullSplats(LodRenderer& lod, const Classification& classification);
  // Hands a finished set to the full level, which may upload a big one on a worker
  // (LodRenderer::beginFullSplats) and take it in a later call. Returns true when one arrived
  // (it may also have failed: then `*error` says why and the old set stays).
  bool takeBuilt(LodRenderer& lod, std::string* error);
  // Waits for a running build and throws its result away (the renderers are replaced).
  void dropBuild();
  // A set is being built, or copied to the GPU: takeBuilt() will hand it over.
  bool building() const { return builder_.busy() || uploading_; }
  // Undo (step < 0) or redo (step > 0) an edit of the function in the next drawAndApply.
  void stepHistory(int step) {
    if (editor_) editor_->requestHistoryStep(step);
  }
  // A transfer-function (or ParaView preset) file to load in the next drawAndApply.
  void loadFile(const std::string& path) {
    if (editor_) editor_->requestFile(path);
  }
  // A preset (its name or key) applied to the function in the next drawAndApply.
  void applyPreset(const std::string& name) {
    if (editor_) editor_->requestPreset(name);
  }
  uint64_t revision() const { return revision_; }

  // The transfer function for the settings file: the file last saved or loaded in the
  // editor, or, when edited since, a copy in `configDir` (written here). Returns the path, or
  // `previous` when there is nothing new; `*error` is set when the copy cannot be written.
  std::string keep(const std::string& configDir, const std::string& previous, std::string* error);

 private:
  const Volume* volume_ = nullptr;
  std::unique_ptr<TfEditor> editor_;
  AsyncSplatBuilder builder_;  // last: destroyed first, joining its worker
  uint64_t revision_ = 0;
  bool uploading_ = false;  // the full level uploads the last set built
};

}  // namespace ewa
