// LodRenderer: a volume at full resolution and its downsampled levels, each drawn by its own
// renderer instance, so a moving view can draw a coarse level and the still view full quality.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "core/async_splat_builder.h"
#include "core/lod_policy.h"
#include "core/splat_attributes.h"
#include "platform/upload_context.h"
#include "render/renderer.h"

namespace ewa {

class SplatRenderer;

// The coarse volumes of every volume factor LodPolicy uses (2, 4, 8, and 16 for big volumes:
// LodPolicy::keepsVolumeFactor), made on the CPU; slow for big volumes, so the viewer makes them
// on its loading thread.
struct LodVolumes {
  std::vector<std::pair<int, std::shared_ptr<const Volume>>> levels;  // (factor, volume)
};
LodVolumes buildLodVolumes(const Volume& volume);

class LodRenderer {
 public:
  using Factory = std::function<std::unique_ptr<Renderer>()>;
  // `factory` makes one renderer per volume factor (the same kind for every level).
  // With `uploads` (a context of the renderers' share group, outliving this object) big splat
  // sets, the full level's and the coarse levels' warmed up, are uploaded on a worker bound to
  // it (SplatRenderer::beginSplats); without, on this thread.
  explicit LodRenderer(Factory factory, platform::UploadContext* uploads = nullptr);

  // `volume` must outlive this object or the next setVolume; the coarse ones are shared.
  void setVolume(const Volume& volume, LodVolumes coarse);
  void setTransferFunction(const TransferFunction& tf);
  // A live edit (a dragged control point): coarse levels classify again on their next render
  // (small volumes, cheap); a full-resolution splat renderer only gets the new table and keeps
  // its splats, and is returned so the caller can build the new set on a worker thread and
  // hand it over with beginFullSplats(). Other full-level renderers take the function as usual.
  SplatRenderer* editTransferFunction(const TransferFunction& tf);
  // The full-resolution renderer when it is a splat renderer (made on first use), else null.
  SplatRenderer* fullSplatRenderer();
  // Gives the full-resolution splat renderer a set built elsewhere (SplatRenderer::beginSplats:
  // a big one is uploaded on a worker, given the upload context); true when it is in place now, or
  // dropped since the full level is not a splat renderer (any more). Else takeUploadedFullSplats()
  // puts it in place once uploaded.
  bool beginFullSplats(ClassifiedSplats splats, const Classification& classification);
  // True when the set beginFullSplats() left to copy is now in place.
  bool takeUploadedFullSplats();
  // True while the full level copies a set beginFullSplats() gave it.
  bool uploadingFullSplats() const;
  // Draws LodPolicy level `level` for a width x height window: the level's volume factor
  // picks the renderer, its image divisor shrinks the image (at least 1x1).
  void render(int level, const Camera& camera, const RenderSettings& settings, int width,
              int height);
  // Makes the images render() of `level` at width x height will draw into, taking about
  // `budgetMs` at most (Renderer::prepareImages: on a worker bound to the upload context where
  // there is one); true once they are there. A window's new size: its first moving frame would
  // otherwise make them itself (fresh memory on llvmpipe: tens of ms for full-size images at
  // 2400x1350). Abandons a full frame under way at the full level, as render() does.
  bool prepareImages(int level, const RenderSettings& settings, int width, int height,
                     double budgetMs);

  // Full quality drawn over several calls (a window's refinement): beginFull starts the full
  // level's frame for a width x height window, each stepFull draws about `budgetMs` of it and
  // returns true once it is done; then the full image is last() (lastLevel() 0). Until then
  // last() and outputTexture() keep the picture drawn before. render() of the full level
  // abandons the frame under way.
  void beginFull(const Camera& camera, const RenderSettings& settings, int width, int height);
  bool stepFull(double budgetMs);
  // The share of the full frame drawn (0..1); 1 when none is under way.
  double fullProgress() const;
  bool fullPending() const { return fullPending_; }
  // The full-resolution renderer (made on first use).
  const Renderer& fullLevel() { return rendererFor(1); }

  // Makes the full-resolution renderer now (it compiles its shaders), so a broken shader
  // fails here, before a window loop starts, instead of on the first frame.
  void prepareFullLevel() { rendererFor(1); }
  // The same, made ready for full-quality frames of width x height under `settings`
  // (Renderer::prepare), so that the first refinement step does not stall on it.
  void prepareFullLevel(const RenderSettings& settings, int width, int height) {
    rendererFor(1).prepare(settings, width, height);
  }

  // One step of readying the coarsest level not drawn since the volume was set, so the first
  // moving frame there does not pay for it: its splats are classified on a worker thread (many
  // UI frames' worth of work), then a later call uploads them and makes the level's programs,
  // images and tables (Renderer::prepare; on llvmpipe most of a UI frame's budget).
  // Calls while the worker classifies return at once; a renderer other than the splat renderer
  // draws a tiny image instead. false when every level had been drawn. Leaves last() as it was;
  // may throw as a draw of the level would.
  bool warmUpNext(const Camera& camera, const RenderSettings& settings);
  // Whether a coarse level has not been drawn since the volume was set, or is being warmed up.
  bool warmUpPending() const;

  // The renderer and image of the last render() (render() must have run).
  const Renderer& last() const { return *renderers_.at(lastFactor_); }
  // 0 before the first render().
  unsigned outputTexture() const {
    const auto it = renderers_.find(lastFactor_);
    return it == renderers_.end() ? 0u : it->second->outputTexture();
  }
  int imageWidth() const { return imageWidth_; }
  int imageHeight() const { return imageHeight_; }
  int lastLevel() const { return lastLevel_; }
  // Whether the coarse volume for `factor` is there (1 always is once a volume is set).
  bool hasFactor(int factor) const;
  // The coarsest LodPolicy level this volume has (LodPolicy::coarsestLevelFor): a level past it
  // is drawn as it; 0 before setVolume.
  int coarsestLevel() const;
  // Bytes of GPU buffers and images all levels' renderers allocated (RenderStats::gpuBytes).
  size_t gpuBytes() const;

 private:
  Renderer& rendererFor(int factor);
  // `level`'s volume factor (the full volume while that coarse one is being built) and image
  // divisor; a level past coarsestLevel() as that one.
  LodLevel resolved(int level) const;
  // The full level's splat renderer if it has been made, else null (makes none).
  SplatRenderer* existingFullSplatRenderer() const;

  Factory factory_;
  platform::UploadContext* uploads_ = nullptr;
  const Volume* volume_ = nullptr;
  LodVolumes coarse_;
  TransferFunction tf_;
  bool hasTf_ = false;
  std::map<int, std::unique_ptr<Renderer>> renderers_;
  std::set<int> drawn_;  // volume factors drawn (or being warmed up) since setVolume
  // A coarse level's splats being classified on a worker, with the volume it reads, kept until
  // the build is taken, even past a setVolume (the build is then dropped). The builder, declared
  // after the volume, is destroyed first: it waits for the build.
  struct WarmUpBuild {
    int factor = 0;
    uint64_t revision = 0;  // revision_ when asked for
    std::shared_ptr<const Volume> volume;
    AsyncSplatBuilder builder;
    bool uploading = false;  // built, and being uploaded on a worker
  };
  std::unique_ptr<WarmUpBuild> warming_;
  uint64_t revision_ = 0;  // counts volume and transfer-function changes (a build goes stale)
  int lastFactor_ = 1;
  int lastLevel_ = 0;
  int imageWidth_ = 0, imageHeight_ = 0;
  bool fullPending_ = false;  // beginFull ran and stepFull has not finished the frame
  int fullWidth_ = 0, fullHeight_ = 0;
};

}  // namespace ewa
