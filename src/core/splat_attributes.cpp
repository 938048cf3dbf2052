// Gradients, surface-voxel classification and the packing of per-splat attributes.
#include "core/splat_attributes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/packing.hpp>

#include "core/named_values.h"
#include "core/parallel_chunks.h"

namespace ewa {

namespace {

constexpr int kTable = 4096;

// Value of voxel (i,j,k) clamped to the volume, NaN read as 0 so gradients stay finite.
double clampedValue(const Volume& v, int64_t i, int64_t j, int64_t k) {
  const auto& d = v.dims();
  i = std::clamp<int64_t>(i, 0, d[0] - 1);
  j = std::clamp<int64_t>(j, 0, d[1] - 1);
  k = std::clamp<int64_t>(k, 0, d[2] - 1);
  const double x = v.value(i, j, k);
  return std::isfinite(x) ? x : 0.0;
}

// Central difference along `axis` at (i,j,k), one-sided at the border, per world unit.
double difference(const Volume& v, int64_t i, int64_t j, int64_t k, int axis) {
  const auto& d = v.dims();
  int64_t p[3] = {i, j, k};
  const int64_t c = p[axis];
  const int64_t lo = std::max<int64_t>(c - 1, 0), hi = std::min<int64_t>(c + 1, d[axis] - 1);
  if (hi == lo) return 0.0;
  p[axis] = hi;
  const double vh = clampedValue(v, p[0], p[1], p[2]);
  p[axis] = lo;
  const double vl = clampedValue(v, p[0], p[1], p[2]);
  return (vh - vl) / (double(hi - lo) * v.spacing()[axis]);
}

constexpr NamedValue<GradientMode> kGradientModeNames[] = {{GradientMode::Central, "central"},
                                                           {GradientMode::Smooth, "smooth"}};
}  // namespace

const char* gradientModeName(GradientMode mode) {
  return nameIn(kGradientModeNames, mode);
}

bool parseGradientMode(const std::string& text, GradientMode* mode) {
  return parseIn(kGradientModeNames, text, mode);
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
  if (mode == GradientMode::Central)
    return {difference(v, i, j, k, 0), difference(v, i, j, k, 1), difference(v, i, j, k, 2)};
  // Sobel-like: the central difference along each axis averaged over the 3x3 neighbours
  // across it with weights [1 2 1] x [1 2 1] / 16, which damps noise in the normals.
  constexpr double w[3] = {0.25, 0.5, 0.25};
  const auto& d = v.dims();
  glm::dvec3 g(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    for (int s = -1; s <= 1; ++s) {
      for (int t = -1; t <= 1; ++t) {
        int64_t p[3] = {i, j, k};
        p[a1] = std::clamp<int64_t>(p[a1] + s, 0, d[a1] - 1);
        p[a2] = std::clamp<int64_t>(p[a2] + t, 0, d[a2] - 1);
        g[axis] += w[s + 1] * w[t + 1] * difference(v, p[0], p[1], p[2], axis);
      }
    }
  }
  return g;
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
