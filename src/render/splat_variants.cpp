// SplatRenderer's choices from the settings: which program variants, slab images and tables a
// frame needs (post-classification, pre-integration, normals), and making them ready.
#include <algorithm>
#include <limits>

#include "core/clip_share.h"
#include "render/splat_renderer.h"

namespace ewa {

bool SplatRenderer::postClassified(const RenderSettings& settings) {
  return ewa::postClassified(settings);
}

bool SplatRenderer::fieldNormals(const RenderSettings& settings) {
  return pairedSlabs(settings) && settings.lighting.enabled &&
         settings.postNormals == PostNormals::Field;
}

bool SplatRenderer::rayNormals(const RenderSettings& settings) {
  return postClassified(settings) && settings.lighting.enabled &&
         settings.postNormals == PostNormals::Ray;
}

bool SplatRenderer::voxelNormalSums(const RenderSettings& settings) {
  return postClassified(settings) && settings.lighting.enabled && !fieldNormals(settings) &&
         !rayNormals(settings);
}

bool SplatRenderer::requestGradients(const RenderSettings& settings) {
  if (!volume_ || !rayNormals(settings)) {
    // A CPU frame under way may read them.
    if (!gradients_.packed().texels.empty()) cancelCpu();
    gradients_.releaseWhenIdle();  // not wanted: freed once no worker packs it
    return false;
  }
  const GradientMode mode = settings.classification.gradient;
  // The CPU splatter reads them in memory, with no texture.
  const GradientUse use = cpuWanted(settings) ? GradientUse::Memory : GradientUse::Texture;
  if (gradients_.holds(*volume_, mode, use)) return false;
  cancelCpu();                              // a CPU frame under way may read the ones held
  gradients_.request(*volume_, mode, use);  // packed, or uploaded from memory, as needed
  return true;
}

SplatVariant SplatRenderer::splatVariant(const RenderSettings& settings, bool texelBuffers) const {
  SplatVariant variant;
  variant.mip = settings.mode == RenderMode::Mip;
  variant.post = postClassified(settings);
  variant.halves = pairedSlabs(settings);
  variant.quarters = quarterSlabs(settings);
  variant.clip = volume_ && !halfSpacesInVolumeFrame(settings.clip, *volume_).empty();
  variant.texelBuffers = texelBuffers;
  variant.erfSeries = usesErfSeries(depthProfile(settings));
  return variant;
}

SlabPassVariant SplatRenderer::slabPassVariant(const RenderSettings& settings, bool scaled) const {
  SlabPassVariant variant;
  variant.post = postClassified(settings);
  variant.preintegrated = pairedSlabs(settings);
  variant.shading = variant.post && settings.lighting.enabled;  // pre-classified: in the sums
  variant.fieldNormals = fieldNormals(settings);
  variant.rayNormals = rayNormals(settings);
  // Front to back the slab drawn before is the segment's front, back to front its back.
  variant.neighbourInFront = variant.preintegrated && settings.order == CompositeOrder::FrontToBack;
  variant.scaled = scaled;
  variant.quarters = quarterSlabs(settings);
  return variant;
}

TargetLayout SplatRenderer::targetLayout(const RenderSettings& settings, int width, int height) {
  return TargetLayout{width,
                      height,
                      pairedSlabs(settings),
                      quarterSlabs(settings),
                      voxelNormalSums(settings),
                      halfFloatSlabs(settings),
                      coarseMarks(settings)};
}

void SplatRenderer::prepare(const RenderSettings& settings, int width, int height) {
  if (width > 0 && height > 0)
    targets_.prepare(targetLayout(settings, width, height),
                     std::numeric_limits<double>::infinity());
  splatPrograms_.select(splatVariant(settings, false));
  programs_->user = nullptr;  // the current variant changed: a frame under way sets its own again
  if (settings.mode != RenderMode::Composite) return;
  slabPrograms_.select(slabPassVariant(settings, false));
  if (settings.coarseSlabs) slabPrograms_.select(slabPassVariant(settings, true));
  // The last frame's view; the table is built again if the next frame's differs.
  if (volume_ && pairedSlabs(settings))
    preparePairTable(settings, slabThickness(settings, volume_->spacing(), lastRotation_));
  requestGradients(settings);  // packed on a worker from now on
}

bool SplatRenderer::prepareImages(const RenderSettings& settings, int width, int height,
                                  double budgetMs) {
  const TargetLayout layout = targetLayout(settings, width, height);
  if (targets_.ready(layout)) return true;
  if (frame_.active) {  // drawn into the images about to change
    waitForPartition();
    frame_.active = false;
  }
  return targets_.prepare(layout, budgetMs, uploads_);
}

bool SplatRenderer::coarseMarks(const RenderSettings& settings) {
  return settings.coarseSlabs && settings.mode == RenderMode::Composite;
}

bool SplatRenderer::pairedSlabs(const RenderSettings& settings) {
  return postClassified(settings) && settings.slabPreintegration;
}

bool SplatRenderer::quarterSlabs(const RenderSettings& settings) {
  return pairedSlabs(settings) && settings.slabSamples >= 4;
}

int SplatRenderer::slabPassesFor(const RenderSettings& settings) const {
  if (settings.slabPasses == 1 || settings.slabPasses == 2) return settings.slabPasses;
  // Auto: timed frames choose where the GPU's timers are used (not on software rasterizers,
  // where two passes always cost more: the fragments are the cost).
  return gpuTimers_ ? 1 + passTuner_.choice() : 1;
}

double SplatRenderer::slabThickness(const RenderSettings& settings, const glm::dvec3& spacing,
                                    const glm::dmat3& rotation) {
  return slabThicknessAlongView(settings.slabThickness, rotation, spacing);
}

double SplatRenderer::preparePairTable(const RenderSettings& settings, double thickness) {
  // Segments run between the values of half (quarter) slabs: the table's colours (their
  // self-attenuation) are for that length.
  const double samples = quarterSlabs(settings) ? 4.0 : 2.0;
  return pairTable_.prepare(tf_, volume_->minValue(), volume_->maxValue(), thickness / samples);
}

}  // namespace ewa
