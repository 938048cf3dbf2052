// tileEwaFrame: footprints, colours and slab lists of a pre-classified frame, made on the CPU as
// the splat shaders and the CPU partition make them.
#include "bench/bench_tile_ewa.h"

#include <algorithm>
#include <cmath>

#include "bench/bench_sprites.h"
#include "core/kernel_reach.h"
#include "core/slab_partition.h"
#include "core/volume_orientation.h"

namespace ewa {

TileEwaFrame tileEwaFrame(const SplatRenderer& r, const Volume& vol, const TransferFunction& tf,
                          const Camera& cam, const RenderSettings& s, int w, int h) {
  TileEwaFrame frame;
  const Projection proj = cam.projection(w, h);
  const glm::dvec3 sp = vol.spacing();
  const double lo = vol.minValue(), hi = vol.maxValue();
  const double voxelVolume = sp.x * sp.y * sp.z;
  const SplatSet& splats = r.splats();
  frame.splats.resize(splats.size());  // invisible ones left zero: no depth, a box nowhere
  forEachFootprint(r, vol, cam, s, w, h, [&](const Footprint& fp, size_t n) {
    const double normalized = SplatSet::normalizedValue(splats.splats()[n]);
    const double value = lo + (hi - lo) * normalized;
    const glm::dvec2 half(std::sqrt(s.cutoff * fp.covariance[0][0]),
                          std::sqrt(s.cutoff * fp.covariance[1][1]));
    TileEwaSplat& out = frame.splats[n];
    out.box = glm::vec4(glm::dvec4(fp.center, half));
    out.conic = glm::vec4(glm::dvec4(fp.conic[0][0], fp.conic[0][1], fp.conic[1][1],
                                     tf.extinctionAt(value) * voxelVolume * fp.peak));
    out.depth = glm::vec4(glm::dvec4(fp.depth, fp.depthSlope, fp.depthSigma));
    out.color = glm::vec4(glm::dvec4(tf.colorAt(value), normalized));
  });
  // The partition as the renderer builds it (SplatRenderer::beginFrame), in the volume's frame.
  const Camera local = cameraInVolumeFrame(cam, vol);
  const FootprintParams params = footprintParams(s, sp);
  DepthExtent extent;
  extent.reach = kernelReach(proj, s.filter, s.cutoff, sp, s.kernelWidth, s.depthCutoff);
  extent.rotation = local.rotation();
  extent.spacing = sp;
  extent.kernelWidth = s.kernelWidth;
  SlabPartition partition;
  // The renderer's slab thickness (SplatRenderer::slabThickness).
  const double thickness = slabThicknessAlongView(s.slabThickness, local.rotation(), sp);
  partition.build(splats, {}, vol.origin(), local.viewMatrix(), thickness, params.cullDepth,
                  extent);
  for (size_t k = 0; k < partition.slabs().size(); ++k) {
    const Slab& slab = partition.slabs()[k];
    frame.slabDepths.emplace_back(float(slab.nearDepth), float(slab.farDepth));
    for (uint32_t e = slab.first; e < slab.first + slab.count; ++e)
      frame.entries.emplace_back(partition.order()[e], uint32_t(k));
  }
  frame.cutoff = float(s.cutoff);
  const DepthProfile profile = depthProfile(s);
  frame.depthProfile = glm::vec2(float(profile.erfReach), float(profile.scale));
  frame.termination = float(s.terminationOpacity);
  return frame;
}

Image8 tileEwaImage(const std::vector<glm::vec4>& picture, int w, int h,
                    const glm::dvec3& background) {
  Image8 out;
  out.width = w;
  out.height = h;
  out.channels = 3;
  out.pixels.assign(size_t(w) * size_t(h) * 3, 0);
  for (int y = 0; y < h && picture.size() >= size_t(w) * size_t(h); ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::vec4 p = picture[size_t(h - 1 - y) * size_t(w) + size_t(x)];
      for (int c = 0; c < 3; ++c) {
        const double v = std::clamp(double(p[c]) + (1.0 - double(p.a)) * background[c], 0.0, 1.0);
        out.pixels[(size_t(y) * size_t(w) + size_t(x)) * 3 + size_t(c)] =
            uint8_t(std::lround(v * 255.0));
      }
    }
  }
  return out;
}

}  // namespace ewa
