// SplatRenderer::writeTileSplats and the rest of what the compute splatter takes from the frame:
// its records from the splat shaders' setup, its variant, the classification's state.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "gl/gl_error.h"
#include "render/clip_uniforms.h"
#include "render/splat_renderer.h"
#include "render/tile_ewa_splatter.h"

namespace ewa {

void SplatRenderer::writeTileSplats(gl::Buffer& out) {
  const size_t count = classified_.splats.size();
  if (!volume_ || count == 0) return;
  if (out.size() < GLsizeiptr(count * sizeof(TileEwaSplat)))
    throw std::invalid_argument("writeTileSplats: the buffer holds fewer records than splats");
  // The frame's own variant (clipped or not), so the footprints come from the same compiled
  // setup.
  const SplatVariant variant = splatVariant(frame_.settings, frame_.texelBuffers);
  gl::Program& pass = tilePrograms()->footprints(variant.key(), variant.defines());
  setCommonUniforms(pass, frame_.camera, frame_.proj, frame_.settings);
  pass.setUInt("uSplatCount", GLuint(count));
  bindFrameState();
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  gl::dispatchOver(pass, count, 64);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  gl::checkGlError("tile splat records");
}

bool SplatRenderer::autoTiles(const RenderSettings& settings) const {
  return settings.splatter == Splatter::Auto && gpuTimers_ && !tilesFailed_ &&
         classified_.splats.size() <= autoTileSplats_ && tileRecordsFit();
}

bool SplatRenderer::tileRecordsFit() const {
  return uint64_t(classified_.splats.size()) * sizeof(TileEwaSplat) <= storageBlockBytes();
}

bool SplatRenderer::tilesWanted(const RenderSettings& settings) const {
  return settings.splatter == Splatter::Tiles ||
         (autoTiles(settings) && splatterTuner_.choice() == 1);
}

bool SplatRenderer::tilesFitStep(double budgetMs) const {
  if (!std::isfinite(budgetMs)) return true;
  // Asked for outright, tiles draw whole frames only: on a software GL one would hold a UI
  // frame for seconds, and without auto's costs nothing would tell.
  if (frame_.settings.splatter != Splatter::Auto) return false;
  const double cost = splatterTuner_.cost(1);
  return cost < 0.0 || cost * double(frameEntryCount()) <= tileStepMs_;
}

void SplatRenderer::reportSplatterCost() {
  if (frame_.settings.splatter == Splatter::Auto) stats_.note = tilesNote_;
  bool post = false, shading = false;
  // With the GPU's timers every whole frame is timed on the GPU, and a budgeted frame's steps
  // wait for their chunks: either way splatMs is the splat stage's whole time.
  if (!autoTiles(frame_.settings) || !tileComposite(post, shading)) return;
  // Per entry of the whole frame: early termination leaves the rasterizer's later slabs
  // undrawn, and what it saves counts for it.
  // A tile frame that compiled programs or made the splatter's buffers paid once for them
  // (counted, that cost could make the tiles look dearer than the rasterizer, and they would not
  // be tried again for many frames): not counted, so the next frame tries the tiles again.
  if (frame_.tiles && frame_.tilesFirstUse) return;
  const size_t entries = frameEntryCount();
  if (entries > 0) splatterTuner_.report(frame_.tiles ? 1 : 0, stats_.splatMs / double(entries));
}

size_t SplatRenderer::frameEntryCount() const {
  size_t entries = 0;
  for (const Slab& slab : frame_.slabs) entries += slab.count;
  return entries;
}

bool SplatRenderer::drawTiles() {
  if (frame_.settings.splatter != Splatter::Auto) return drawTilesNow();
  try {
    return drawTilesNow();
  } catch (const gl::GlError& e) {
    // A GL whose compiler rejects the tiles' programs (they have run on Mesa and NVIDIA only):
    // auto rasterizes instead, and every frame's statistics say why.
    tilesFailed_ = true;
    const std::string what = e.what();
    tilesNote_ = "compute tiles unavailable, frames rasterized: " + what.substr(0, what.find('\n'));
    return false;
  }
}

const std::shared_ptr<TileEwaPrograms>& SplatRenderer::tilePrograms() {
  // Made on first use, in the set the renderers of the window's levels share.
  if (!programs_->tiles) programs_->tiles = std::make_shared<TileEwaPrograms>(shaders_, 16);
  return programs_->tiles;
}

bool SplatRenderer::drawTilesNow() {
  // The tiles read their records as one storage block: past its end they read nothing (the
  // records of a 512^3 volume, larger than a GPU's block may be, drew rings with gaps).
  if (!tileRecordsFit()) {
    constexpr uint64_t kMiB = 1024 * 1024;
    const uint64_t records = uint64_t(classified_.splats.size()) * sizeof(TileEwaSplat);
    stats_.note = "compute tiles' splat records (" + std::to_string(records / kMiB) +
                  " MiB) exceed the GL's storage block (" +
                  std::to_string(storageBlockBytes() / kMiB) + " MiB): rasterized";
    return false;
  }
  const size_t compiled = tilePrograms()->compiled();
  frame_.tilesFirstUse = !tiles_;
  if (!tiles_) tiles_ = std::make_unique<TileEwaSplatter>(tilePrograms());
  if (!loadTiles(*tiles_)) return false;
  tiles_->draw(frame_.width, frame_.height);
  frame_.tilesFirstUse = frame_.tilesFirstUse || tilePrograms()->compiled() != compiled;
  // The GPU's counts are read after the final pass (stepFrame), as for rasterized frames.
  if (!frame_.indirect)
    stats_.slabEntries = frame_.gpuSlabs ? gpuPartition_->entryCount() : frameEntryCount();
  stats_.slabsDrawn = frame_.gpuSlabs ? gpuPartition_->slabs().size() : frame_.slabs.size();
  frame_.tiles = stats_.tiles = true;
  stats_.slabPasses = 0;  // no splat passes: each tile adds its slabs' quarters at once
  return true;
}

bool SplatRenderer::tileComposite(bool& post, bool& shading) const {
  const RenderSettings& s = frame_.settings;
  post = postClassified(s);
  shading = fieldNormals(s) || rayNormals(s);
  if (s.mode != RenderMode::Composite || s.order != CompositeOrder::FrontToBack) return false;
  return !post || (quarterSlabs(s) && (shading || !s.lighting.enabled));
}

bool SplatRenderer::loadTiles(TileEwaSplatter& tiles) {
  TileEwaFrame tileFrame;
  if (!tileComposite(tileFrame.post, tileFrame.shading) || classified_.splats.size() == 0)
    return false;
  const RenderSettings& s = frame_.settings;
  tileFrame.rayNormals = rayNormals(s);
  tileFrame.cutoff = float(s.cutoff);
  const DepthProfile profile = depthProfile(s);
  tileFrame.depthProfile = glm::vec2(float(profile.erfReach), float(profile.scale));
  tileFrame.termination = float(s.terminationOpacity);
  if (!frame_.gpuSlabs) {
    // The CPU partition's lists, front to back: each entry with its slab's number.
    const std::vector<uint32_t>& order = partition_.order();
    for (size_t k = 0; k < frame_.slabs.size(); ++k) {
      const Slab& slab = frame_.slabs[k];
      tileFrame.slabDepths.emplace_back(float(slab.nearDepth), float(slab.farDepth));
      for (size_t e = slab.first; e < slab.first + slab.count; ++e)
        tileFrame.entries.emplace_back(order[e], uint32_t(k));
    }
  }
  tiles.setFrame(tileFrame);  // no splats: the records are made on the GPU below
  if (frame_.gpuSlabs) {
    // llvmpipe's composite runs in chunks of slabs sized by their counts (a short wait).
    if (softwareGl_) gpuPartition_->readCounts();
    tiles.useGpuSlabLists(*gpuPartition_);
  }
  tiles.reserveSplats(classified_.splats.size());
  writeTileSplats(tiles.splatBuffer());
  prepareTileComposite(tiles.compositeProgram());
  return true;
}

void SplatRenderer::prepareTileComposite(gl::Program& program) {
  if (!volume_) return;
  setClipUniforms(program, frame_.settings.clip, *volume_, frame_.camera, frame_.proj);
  if (!postClassified(frame_.settings)) return;
  setClassifyUniforms(program, frame_.proj, frame_.settings);
  if (pairedSlabs(frame_.settings)) pairTable_.bindUnits(kPairTableUnit, kPairPrefixUnit);
  gradients_.bindUnit(kGradientUnit);
}

}  // namespace ewa
