// Gradients, surface-voxel classification and the packing of per-splat attributes.
#include "core/splat_attributes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/packing.hpp>

#include "core/gradient_stencil.h"
#include "core/named_values.h"
#include "core/parallel_chunks.h"

namespace ewa {

namespace {

constexpr int kTable = 4096;

constexpr NamedValue<GradientMode> kGradientModeNames[] = {{GradientMode::Central, "central"},
                                                           {GradientMode::Smooth, "smooth"}};
}  // namespace

const char* gradientModeName(GradientMode mode) {
  return nameIn(kGradientModeNames, mode);
}

bool parseGradientMode(const std::string& text, GradientMode* mode) {
  return parseIn(kGradientModeNames, text, mode);
}

std::vector<std::string> gradientModeNames() {
  return namesIn(kGradientModeNames);
}

PackedAttributes packAttributes(const glm::dvec3& n, bool surface, double offset) {
  const float kind = surface ? float(3.0 + std::clamp(offset, -1.0, 1.0)) : 0.0f;
  return {glm::packHalf2x16(glm::vec2(n.x, n.y)), glm::packHalf2x16(glm::vec2(float(n.z), kind))};
}

UnpackedAttributes unpackAttributes(const PackedAttributes& a) {
  const glm::vec2 xy = glm::unpackHalf2x16(a.nxy), zk = glm::unpackHalf2x16(a.nzKind);
  UnpackedAttributes u;
  u.normal = glm::dvec3(xy.x, xy.y, zk.x);
  u.surface = zk.y >= 1.0f;
  u.offset = u.surface ? zk.y - 3.0 : 0.0;
  return u;
}

glm::dvec3 volumeGradient(const Volume& v, int64_t i, int64_t j, int64_t k, GradientMode mode) {
  auto read = [&v](int64_t n) {
    const double x = v.valueAt(n);
    return std::isfinite(x) ? x : 0.0;  // NaN read as 0, so gradients stay finite
  };
  const int64_t p[3] = {i, j, k};
  return GradientStencil(v.dims(), v.spacing(), read).at(p, mode);
}

ClassifiedSplats classifySplats(const Volume& volume, const TransferFunction& tf,
                                const Classification& c, size_t maxSplats, unsigned threads) {
  ClassifiedSplats out;
  const double lo = volume.minValue(), hi = volume.maxValue();
  const double width = hi > lo ? hi - lo : 1.0;
  // Opacity by value through a table, as SplatSet::build does, so no per-voxel search.
  std::vector<double> alpha(kTable);
  for (int t = 0; t < kTable; ++t) alpha[t] = tf.alphaAt(lo + width * t / (kTable - 1));
  auto alphaOf = [&](double v) {
    if (!std::isfinite(v)) return 0.0;
    return alpha[std::clamp(int(std::lround((v - lo) / width * (kTable - 1))), 0, kTable - 1)];
  };
  // The classified quantity the surface criterion thresholds: the value or its opacity.
  auto level = [&](double v) { return c.surface == SurfaceCriterion::Opacity ? alphaOf(v) : v; };
  const auto& d = volume.dims();
  auto onSurface = [&](int64_t i, int64_t j, int64_t k, double v) {
    if (c.surface == SurfaceCriterion::None || !std::isfinite(v) || !(level(v) >= c.threshold))
      return false;
    const int64_t nb[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                              {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
    for (const auto& q : nb) {
      if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= d[0] || q[1] >= d[1] || q[2] >= d[2])
        continue;
      const double w = volume.value(q[0], q[1], q[2]);
      if (std::isfinite(w) && level(w) < c.threshold) return true;
    }
    return false;
  };
  const bool post = c.mode == ClassificationMode::Post;
  auto keep = [&](int64_t i, int64_t j, int64_t k, double v) { return onSurface(i, j, k, v); };
  const auto isVisible = [&tf](double v) { return tf.alphaAt(v) > 0.0; };
  std::vector<uint8_t> needed;
  if (post) needed = postClassificationMask(volume, isVisible, c.postMarginSquared, threads);
  auto inMask = [&](int64_t i, int64_t j, int64_t k, double) {
    return needed[size_t(volume.index(i, j, k))] != 0;
  };
  out.splats =
      SplatSet::build(volume, isVisible, 1,
                      post                                  ? SplatSet::VoxelPredicate(inMask)
                      : c.surface == SurfaceCriterion::None ? SplatSet::VoxelPredicate()
                                                            : SplatSet::VoxelPredicate(keep),
                      maxSplats, threads);
  // Voxels are kept by their own values (above); only what the splats carry is sharpened.
  if (post) prefilterSplatValues(volume, c.prefilter, &out.splats, threads);
  const double minSpacing = std::min({volume.spacing().x, volume.spacing().y, volume.spacing().z});
  const SplatList& splats = out.splats.splats();
  out.attributes.resize(splats.size());
  // Each splat's normal and kind depend on its own neighbourhood only: the splats are split
  // between the machine's cores (the gradients are most of classification's time after the mask).
  auto attributes = [&](size_t first, size_t last, size_t* surfaces) {
    size_t surfaceCount = 0;  // written out once: counters side by side share a cache line
    for (size_t n = first; n < last; ++n) {
      const PackedSplat& s = splats[n];
      const int64_t i = SplatSet::i(s), j = SplatSet::j(s), k = SplatSet::k(s);
      const double v = volume.value(i, j, k);
      const glm::dvec3 g = volumeGradient(volume, i, j, k, c.gradient);
      const double mag = glm::length(g);
      // Below this the direction is rounding noise: the splat stays unshaded.
      const bool hasNormal = mag * minSpacing > 1e-6 * width;
      const glm::dvec3 nrm = hasNormal ? -g / mag : glm::dvec3(0.0);
      bool surface = !post && hasNormal && onSurface(i, j, k, v);
      if (surface && c.surface == SurfaceCriterion::Opacity)
        surface = mag * minSpacing >= c.minGradient * width;
      // Onto the iso-surface by one Newton step along the gradient (value criterion only).
      const double offset = surface && c.surface == SurfaceCriterion::Value
                                ? (v - c.threshold) / (mag * minSpacing)
                                : 0.0;
      surfaceCount += surface ? 1 : 0;
      out.attributes[n] = packAttributes(nrm, surface, offset);
    }
    *surfaces = surfaceCount;
  };
  const std::vector<size_t> surfaces = parallelChunkResults<size_t>(
      splats.size(), kMinChunkWork, threads, [&](size_t first, size_t last) {
        size_t count = 0;
        attributes(first, last, &count);
        return count;
      });
  for (size_t count : surfaces) out.surfaceCount += count;
  return out;
}

}  // namespace ewa
