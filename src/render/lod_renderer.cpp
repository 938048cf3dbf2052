// LodRenderer: one renderer instance per level of detail, created on first use.
#include "render/lod_renderer.h"

#include <algorithm>
#include <stdexcept>

#include "core/volume_downsample.h"
#include "render/splat_renderer.h"

namespace ewa {

LodVolumes buildLodVolumes(const Volume& volume) {
  LodVolumes out;
  std::vector<int> factors;
  for (const LodLevel& l : LodPolicy::kLevels)
    if (l.volumeFactor > 1 && LodPolicy::keepsVolumeFactor(l.volumeFactor, volume.voxelCount()) &&
        std::find(factors.begin(), factors.end(), l.volumeFactor) == factors.end())
      factors.push_back(l.volumeFactor);
  std::shared_ptr<const Volume> previous;
  int previousFactor = 1;
  for (int f : factors) {
    // 4 = 2 x 2: downsampling the half-size volume again is 8x cheaper than the full one.
    if (previous && f % previousFactor == 0)
      previous = std::make_shared<Volume>(downsampleVolume(*previous, f / previousFactor));
    else
      previous = std::make_shared<Volume>(downsampleVolume(volume, f));
    previousFactor = f;
    out.levels.emplace_back(f, previous);
  }
  return out;
}

LodRenderer::LodRenderer(Factory factory, platform::UploadContext* uploads)
    : factory_(std::move(factory)), uploads_(uploads) {}

void LodRenderer::setVolume(const Volume& volume, LodVolumes coarse) {
  volume_ = &volume;
  coarse_ = std::move(coarse);
  drawn_.clear();
  ++revision_;
  for (auto& [factor, renderer] : renderers_) {
    if (factor == 1) {
      renderer->setVolume(volume);
      continue;
    }
    const Volume* v = nullptr;
    for (const auto& [f, vol] : coarse_.levels)
      if (f == factor) v = vol.get();
    renderer->setVolume(v ? *v : volume);
  }
}

void LodRenderer::setTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  hasTf_ = true;
  ++revision_;
  for (auto& entry : renderers_) entry.second->setTransferFunction(tf);
}

SplatRenderer* LodRenderer::editTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  hasTf_ = true;
  ++revision_;
  SplatRenderer* live = nullptr;
  for (auto& [factor, renderer] : renderers_) {
    auto* splat = factor == 1 ? dynamic_cast<SplatRenderer*>(renderer.get()) : nullptr;
    if (splat) {
      splat->updateTransferTexture(tf);
      live = splat;
    } else {
      renderer->setTransferFunction(tf);
    }
  }
  return live;
}

SplatRenderer* LodRenderer::fullSplatRenderer() {
  if (!volume_) return nullptr;
  return dynamic_cast<SplatRenderer*>(&rendererFor(1));
}

SplatRenderer* LodRenderer::existingFullSplatRenderer() const {
  const auto it = renderers_.find(1);
  return it == renderers_.end() ? nullptr : dynamic_cast<SplatRenderer*>(it->second.get());
}

bool LodRenderer::beginFullSplats(ClassifiedSplats splats, const Classification& classification) {
  SplatRenderer* splat = existingFullSplatRenderer();
  return !splat || splat->beginSplats(std::move(splats), classification);
}

bool LodRenderer::takeUploadedFullSplats() {
  SplatRenderer* splat = existingFullSplatRenderer();
  return splat && splat->takeUploadedSplats();
}

bool LodRenderer::uploadingFullSplats() const {
  const SplatRenderer* splat = existingFullSplatRenderer();
  return splat && splat->uploadingSplats();
}

bool LodRenderer::hasFactor(int factor) const {
  if (factor == 1) return volume_ != nullptr;
  for (const auto& level : coarse_.levels)
    if (level.first == factor) return true;
  return false;
}

Renderer& LodRenderer::rendererFor(int factor) {
  auto it = renderers_.find(factor);
  if (it != renderers_.end()) return *it->second;
  std::unique_ptr<Renderer> r = factory_();
  if (auto* splat = dynamic_cast<SplatRenderer*>(r.get())) splat->setUploadContext(uploads_);
  const Volume* v = volume_;
  for (const auto& [f, vol] : coarse_.levels)
    if (f == factor) v = vol.get();
  if (v) r->setVolume(*v);
  if (hasTf_) r->setTransferFunction(tf_);
  return *renderers_.emplace(factor, std::move(r)).first->second;
}

void LodRenderer::render(int level, const Camera& camera, const RenderSettings& settings, int width,
                         int height) {
  if (!volume_) throw std::logic_error("LodRenderer::render before setVolume");
  level = std::clamp(level, 0, coarsestLevel());
  const LodLevel lod = resolved(level);
  imageWidth_ = std::max(1, width / lod.imageDivisor);
  imageHeight_ = std::max(1, height / lod.imageDivisor);
  if (lod.volumeFactor == 1) fullPending_ = false;
  rendererFor(lod.volumeFactor).render(camera, settings, imageWidth_, imageHeight_);
  drawn_.insert(lod.volumeFactor);
  lastFactor_ = lod.volumeFactor;
  lastLevel_ = level;
}

int LodRenderer::coarsestLevel() const {
  return volume_ ? LodPolicy::coarsestLevelFor(volume_->voxelCount()) : 0;
}

LodLevel LodRenderer::resolved(int level) const {
  LodLevel lod = LodPolicy::level(std::clamp(level, 0, coarsestLevel()));
  if (!hasFactor(lod.volumeFactor)) lod.volumeFactor = 1;  // still being built: full volume
  return lod;
}

bool LodRenderer::prepareImages(int level, const RenderSettings& settings, int width, int height,
                                double budgetMs) {
  if (!volume_) throw std::logic_error("LodRenderer::prepareImages before setVolume");
  const LodLevel lod = resolved(level);
  Renderer& renderer = rendererFor(lod.volumeFactor);
  const int w = std::max(1, width / lod.imageDivisor), h = std::max(1, height / lod.imageDivisor);
  if (lod.volumeFactor == 1) fullPending_ = false;  // as render() of the full level does
  return renderer.prepareImages(settings, w, h, budgetMs);
}

void LodRenderer::beginFull(const Camera& camera, const RenderSettings& settings, int width,
                            int height) {
  if (!volume_) throw std::logic_error("LodRenderer::beginFull before setVolume");
  fullWidth_ = std::max(1, width);
  fullHeight_ = std::max(1, height);
  fullPending_ = true;
  rendererFor(1).beginFrame(camera, settings, fullWidth_, fullHeight_);
}

bool LodRenderer::stepFull(double budgetMs) {
  if (!fullPending_) return true;
  if (!rendererFor(1).stepFrame(budgetMs)) return false;
  fullPending_ = false;
  imageWidth_ = fullWidth_;
  imageHeight_ = fullHeight_;
  lastFactor_ = 1;
  lastLevel_ = 0;
  return true;
}

double LodRenderer::fullProgress() const {
  if (!fullPending_) return 1.0;
  const auto it = renderers_.find(1);
  return it == renderers_.end() ? 0.0 : it->second->frameProgress();
}

bool LodRenderer::warmUpNext(const Camera& camera, const RenderSettings& settings) {
  constexpr int kWarmUpSize = 8;
  if (warming_ && warming_->uploading) {
    auto& splat = dynamic_cast<SplatRenderer&>(rendererFor(warming_->factor));
    bool taken = false;
    try {
      // Dropped when another volume or function came since, or a draw of the level took it.
      if (warming_->revision == revision_ && splat.uploadingSplats()) {
        taken = splat.takeUploadedSplats();
        if (!taken) return true;  // still uploading
      }
    } catch (const std::exception&) {
      // The upload failed: the level's first draw classifies and uploads again, and says why.
    }
    warming_.reset();
    if (taken) splat.prepare(settings, kWarmUpSize, kWarmUpSize);
    return true;
  }
  if (warming_) {
    std::optional<BuiltSplats> built;
    try {
      built = warming_->builder.poll();
      if (!built) return true;  // still classifying
    } catch (const std::exception&) {
      // Too many splats: the level's first draw says so, as without a warm-up.
    }
    const int factor = warming_->factor;
    // Dropped: another volume or transfer function since, or no set.
    if (warming_->revision != revision_ || !built) {
      warming_.reset();
      return true;
    }
    // Only a splat renderer asks for a build; a draw of the level meanwhile classified it.
    auto& splat = dynamic_cast<SplatRenderer&>(rendererFor(factor));
    if (!splat.needsSplats(built->classification)) {
      warming_.reset();
      return true;
    }
    // Uploaded (a big set on a worker, taken in a later call), and the programs, images and
    // tables made: a tiny draw would also run every splat through the vertex stage (on llvmpipe
    // far more than a UI frame's budget for any but small volumes).
    splat.updateTransferTexture(tf_);
    try {
      warming_->uploading = !splat.beginSplats(std::move(built->splats), built->classification);
    } catch (const std::exception&) {
      // Too many splats for the order entries: the level's first draw says so.
      warming_.reset();
      return true;
    }
    if (warming_->uploading) return true;
    warming_.reset();
    splat.prepare(settings, kWarmUpSize, kWarmUpSize);
    return true;
  }
  // Coarsest first: the cheapest, and the first moving level after a slow full frame.
  for (auto level = coarse_.levels.rbegin(); level != coarse_.levels.rend(); ++level) {
    if (!drawn_.insert(level->first).second) continue;
    Renderer& renderer = rendererFor(level->first);
    auto* splat = dynamic_cast<SplatRenderer*>(&renderer);
    const Classification wanted = splatClassification(settings);
    if (splat && hasTf_ && splat->needsSplats(wanted)) {
      warming_ = std::make_unique<WarmUpBuild>();
      warming_->factor = level->first;
      warming_->revision = revision_;
      warming_->volume = level->second;
      warming_->builder.request(*warming_->volume, tf_, wanted, splat->maxSplats());
      return true;
    }
    renderer.render(camera, settings, kWarmUpSize, kWarmUpSize);  // other renderers: drawn
    return true;
  }
  return false;
}

bool LodRenderer::warmUpPending() const {
  if (warming_) return true;
  for (const auto& level : coarse_.levels)
    if (drawn_.count(level.first) == 0) return true;
  return false;
}

size_t LodRenderer::gpuBytes() const {
  size_t bytes = 0;
  for (const auto& [factor, renderer] : renderers_) bytes += renderer->stats().gpuBytes;
  return bytes;
}

}  // namespace ewa
