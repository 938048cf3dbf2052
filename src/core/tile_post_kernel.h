// The CPU splatter's per-tile gathers besides the pre-classified composite: post-classified
// slabs (kernel-weighted values in 1, 2 or 4 depth samples a slab, classified per pixel as the
// slab pass classifies them, shaders/slab_composite.frag.glsl), X-ray and MIP. Compiled once
// per instruction set like tile_composite_kernel.h, which it follows; include it after that
// header, from tile_compositor.cpp and tile_compositor_avx2.cpp only.
#pragma once

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/covered_length.h"
#include "core/field_gradient.h"
#include "core/gradient_volume.h"
#include "core/shading.h"
#include "core/slab_preintegration.h"
#include "core/splat_records.h"

namespace ewa::tile_kernel::EWA_TILE_ISA {

// A post-classified slab's shares between `Samples` + 1 depth bounds: the slab's planes split
// in equal parts (the quarters' third bound is the far plane less a quarter, the halves' middle
// the planes' mean, as shaders/ewa_footprint.glsl's slabQuarters and slabHalves), an open bound
// unbounded, each clamped to the kept depths.
template <int Samples>
__attribute__((always_inline)) inline void sampleBounds(float zNear, float zFar, bool openNear,
                                                        bool openFar, float bounds[Samples + 1]) {
  const float unbounded = float(kClipUnbounded);
  bounds[0] = openNear ? -unbounded : zNear;
  bounds[Samples] = openFar ? unbounded : zFar;
  if (Samples == 2) bounds[1] = 0.5f * (zNear + zFar);
  if (Samples == 4) {
    const float q = 0.25f * (zFar - zNear);
    bounds[1] = zNear + q;
    bounds[2] = 0.5f * (zNear + zFar);
    bounds[3] = zFar - q;
  }
}

// The depth bounds each of a slab's samples covers for its covered length.
template <int Samples>
inline void sampleSpans(float zNear, float zFar, float lo[Samples], float hi[Samples]) {
  float b[Samples + 1];
  sampleBounds<Samples>(zNear, zFar, false, false, b);
  for (int k = 0; k < Samples; ++k) {
    lo[k] = b[k];
    hi[k] = b[k + 1];
  }
}

// A pixel's post-classified slab: its samples' values (kernel-weighted means; a sample
// without weight takes the slab's mean, a half the other half's) and covered lengths.
template <int Samples>
struct SlabSamples {
  float value[Samples];
  float length[Samples];
};

template <int Samples>
inline SlabSamples<Samples> slabSamplesOf(const float* sv, const float* sw, float boxNear,
                                          float boxFar, float stretch, float zNear, float zFar) {
  SlabSamples<Samples> out;
  float lo[Samples], hi[Samples];
  sampleSpans<Samples>(zNear, zFar, lo, hi);
  for (int k = 0; k < Samples; ++k)
    out.length[k] = coveredLengthOf(lo[k], hi[k], boxNear, boxFar, stretch, sw[k]);
  if (Samples == 2) {  // halfValues
    const float front = sw[0] > 0.0f ? sv[0] / sw[0] : sv[1] / sw[1];
    const float back = sw[1] > 0.0f ? sv[1] / sw[1] : front;
    out.value[0] = std::clamp(front, 0.0f, 1.0f);
    out.value[Samples - 1] = std::clamp(back, 0.0f, 1.0f);
    return out;
  }
  // quarterValues; one sample: the slab's mean.
  float sum = 0.0f, weight = 0.0f;
  for (int k = 0; k < Samples; ++k) {
    sum += sv[k];
    weight += sw[k];
  }
  const float mean = sum / std::max(weight, 1e-30f);
  for (int k = 0; k < Samples; ++k)
    out.value[k] = std::clamp(sw[k] > 0.0f ? sv[k] / sw[k] : mean, 0.0f, 1.0f);
  return out;
}

// A pixel's head light on a post-classified slab's segments (shaders/slab_classify.glsl's
// Surface, surfaceFrom and surfaceAt): the direction to the eye and, by voxel or field normals,
// the slab's summed normal or the field's gradient; by ray normals each segment's from the
// data's gradient at its middle.
template <TileNormals Normals>
struct SegmentLight {
  const TileCompositeSettings* settings = nullptr;
  glm::vec3 toEye{0.0f, 0.0f, 1.0f};
  glm::vec3 normal{0.0f};  // Voxel, Field: unit, or zero (unlit)
  glm::vec3 origin{0.0f};  // Ray: the pixel's ray in index coordinates (indexRay)
  glm::vec3 direction{0.0f};
  glm::mat3 toCamera{1.0f};  // Ray: index-space gradients to camera space

  // The frame's turn of index-space gradients into camera space (rayGradient's transpose of
  // the camera-to-index matrix), for SegmentLight's constructor.
  static glm::mat3 gradientToCamera(const TileCompositeSettings& s) {
    return glm::mat3(glm::transpose(glm::dmat3(s.cameraToIndex)));
  }

  // The light at the pixel centred at `centre` (voxel normals: with the summed normals `sum`;
  // field normals: the field's gradient; ray normals: `turn`, gradientToCamera).
  SegmentLight(const TileCompositeSettings& s, const glm::dvec2& centre, const glm::vec3& sum,
               const glm::mat3& turn)
      : settings(&s), toCamera(turn) {
    if constexpr (Normals == TileNormals::None) return;
    if (!s.proj.orthographic) {
      const glm::dvec2 q = (centre - s.proj.principal) / s.proj.focalPixels;
      toEye = glm::vec3(glm::normalize(glm::dvec3(-q, 1.0)));
    }
    if constexpr (Normals == TileNormals::Voxel || Normals == TileNormals::Field) {
      const float length = glm::length(sum);
      normal = length > 0.0f ? sum / length : glm::vec3(0.0f);
    }
    if constexpr (Normals == TileNormals::Ray) {
      const IndexRay ray = indexRay(s.cameraToIndex, s.proj, centre);
      origin = glm::vec3(ray.origin);
      direction = glm::vec3(ray.direction);
    }
  }

  // The premultiplied segment `c` lit, its normal (ray normals) read at camera depth `depth`
  // where it has opacity.
  glm::vec4 operator()(const glm::vec4& c, float depth) const {
    if constexpr (Normals == TileNormals::None) {
      return c;
    } else {
      glm::vec3 n = normal;
      if constexpr (Normals == TileNormals::Ray) {
        if (!(c.a > 0.0f)) return c;
        // rayGradient: the texture read at the point's index coordinates, turned to camera space.
        const glm::vec3 g =
            toCamera * sampleGradientOf(*settings->gradients, origin + depth * direction);
        const float length = glm::length(g);
        n = length > 0.0f ? g / length : glm::vec3(0.0f);
      }
      const HeadlightTerms<float> t = headlightTermsOf(n, toEye, settings->lighting);
      return glm::vec4(glm::vec3(c) * t.gain + t.white * c.a, c.a);
    }
  }
};

// The slab's premultiplied colour at a pixel: pre-integrated, the segments between its samples'
// values and, on the side of the slab drawn before it, the neighbour's nearest value
// (`neighbour`; none: the slab's own), over each sample's covered length; one sample, its mean
// value classified through the 1D transfer function over its covered length. Each segment lit
// by `light` at its middle: segment i at the slab's near plane plus i (back to front i + 1)
// samples' depths (segmentMiddles), the one sample at the slab's middle.
template <int Samples, typename Light>
inline glm::vec4 classifySlab(const SlabSamples<Samples>& s, bool hasNeighbour, float neighbour,
                              bool backToFront, const TileClassifyTables& t, float zNear,
                              float zFar, const Light& light) {
  if (Samples == 1) {
    const glm::vec4 tf = transferAt(t.transfer, t.transferSize, s.value[0]);
    const float depth = s.length[0] * tf.a;
    if (!(depth > 0.0f)) return glm::vec4(0.0f);
    const float alpha = 1.0f - expOf(-depth);
    return light(glm::vec4(glm::vec3(tf) * alpha, alpha), 0.5f * (zNear + zFar));
  }
  // The values in depth order; segment i runs from value i to value i + 1.
  float v[Samples + 1];
  for (int k = 0; k < Samples; ++k) v[backToFront ? k : k + 1] = s.value[k];
  if (backToFront)
    v[Samples] = hasNeighbour ? neighbour : s.value[Samples - 1];
  else
    v[0] = hasNeighbour ? neighbour : s.value[0];
  const float step = (zFar - zNear) / float(Samples);
  const float first = backToFront ? zNear + step : zNear;
  glm::vec4 sum(0.0f);
  for (int i = 0; i < Samples; ++i) {
    const glm::vec4 c = light(classifySlabPairOf(t.pairTexels, t.pairSize, t.prefix, t.prefixSize,
                                                 v[i], v[i + 1], s.length[i]),
                              first + step * float(i));
    sum += (1.0f - sum.a) * c;
  }
  return sum;
}

template <TileNormals Normals>
constexpr bool kFieldNormals = Normals == TileNormals::Field;

// Field normals: a slab's sums at the border of one pixel about a tile (weight * value and
// weight over the slab) and its pixels' kept depths: the row below the tile, the row above,
// the column left of it and the column right, each along the tile's side.
struct TileBorder {
  static constexpr int kSides = 4;
  static constexpr int kTile = TileCompositor::kTile;
  float sum[kSides][kTile], weight[kSides][kTile];
  float keptNear[kSides][kTile], keptFar[kSides][kTile];

  // Picture pixel (x, y) of side `side`'s place `i`.
  static void pixel(const TileWork& work, int side, int i, int& x, int& y) {
    x = side < 2 ? work.px0 + i : side == 2 ? work.px0 - 1 : work.px0 + work.w;
    y = side >= 2 ? work.py0 + i : side == 0 ? work.py0 - 1 : work.py0 + work.h;
  }
  void clear() {
    for (int side = 0; side < kSides; ++side)
      for (int i = 0; i < kTile; ++i) sum[side][i] = weight[side][i] = 0.0f;
  }
  // No sums; the kept depths as beginTile's (clipped: the clip region along each pixel's ray).
  void begin(const TileWork& work, bool clipped) {
    clear();
    const TileCompositeSettings& s = *work.settings;
    for (int side = 0; side < kSides; ++side)
      for (int i = 0; i < kTile; ++i) {
        keptNear[side][i] = -float(kClipUnbounded);
        keptFar[side][i] = float(kClipUnbounded);
        if (!clipped) continue;
        int x, y;
        pixel(work, side, i, x, y);
        const RayInterval kept = clippedDepths(s.clipPlanes, s.proj, glm::dvec2(x + 0.5, y + 0.5));
        keptNear[side][i] = float(std::clamp(kept.near, -kClipUnbounded, kClipUnbounded));
        keptFar[side][i] = std::max(keptNear[side][i],
                                    float(std::clamp(kept.far, -kClipUnbounded, kClipUnbounded)));
      }
  }
};

// The post-classified tile: each slab's kernels add (weight * value, weight) per pixel and
// sample (their share of each sample's depths, exactly, cut to the kept depths), then every
// pixel classifies the slab and composites it, the slab before kept for its nearest value; lit
// by `Normals`. Voxel normals: the kernels add weight * normal too. Field normals: the
// pixels of the tile and of a border of one pixel about it add their sums whether or not they
// take more slabs (their neighbours' gradients read them), the tile's items being binned with
// that border (TileCompositor::draw).
template <int Samples, bool Series, bool Clipped, TileNormals Normals>
__attribute__((always_inline)) inline void postTileOf(const TileWork& work) {
  constexpr bool kVoxel = Normals == TileNormals::Voxel;
  constexpr int kTile = TileCompositor::kTile;
  const TileCompositeSettings& s = *work.settings;
  const int px0 = work.px0, py0 = work.py0;
  const float cutoff = float(s.cutoff);
  const bool backToFront = s.backToFront;
  const float termination = backToFront ? 2.0f : float(s.termination);
  const float erfReach = float(std::min(s.profile.erfReach, kClipUnbounded));
  const float halfScale = 0.5f * float(s.profile.scale);
  TileCompositor::TileState& state = *work.state;
  if (!state.begun) beginTile(work, Clipped, true);
  // The pixel loops' inputs on the stack, where the compiler sees that nothing else writes them.
  alignas(32) float live[kPixels], keptNear[kPixels], keptFar[kPixels];
  std::copy_n(state.live, kPixels, live);
  if (Clipped) {
    std::copy_n(state.keptNear, kPixels, keptNear);
    std::copy_n(state.keptFar, kPixels, keptFar);
  }
  float* last = state.last;  // the slab before's nearest value
  bool* hasLast = state.hasLast;
  const float* boxNear = state.boxNear;
  const float* boxFar = state.boxFar;
  const float* stretch = state.stretch;
  TilePlanes image;
  loadTile(work, image);
  const glm::mat3 toCamera = SegmentLight<Normals>::gradientToCamera(s);  // ray normals
  // Weight * value and weight, each plane 64 bytes past the last's end: planes a multiple of
  // 4 KiB apart (a sample's two, back to back) can make a load wait on a store to the other,
  // their addresses' low 12 bits being alike; the pixel loops ran some 3% slower so.
  constexpr int kStride = kPixels + 16;
  alignas(64) float samplePlanes[2 * Samples][kStride];
  float(*const sv)[kStride] = samplePlanes;
  float(*const sw)[kStride] = samplePlanes + Samples;
  for (int p = 0; p < kPixels; ++p)
    for (int k = 0; k < Samples; ++k) sv[k][p] = sw[k][p] = 0.0f;
  // Voxel normals: the slab's weight * normal, x, y and z.
  alignas(32) float sn[kVoxel ? 3 : 1][kVoxel ? kPixels : 1];
  if constexpr (kVoxel)
    for (int p = 0; p < kPixels; ++p) sn[0][p] = sn[1][p] = sn[2][p] = 0.0f;
  // Field normals: the pixels that add (those in the picture), and the border's sums.
  alignas(32) float inside[kFieldNormals<Normals> ? kPixels : 1];
  LiveRows insideRows;
  TileBorder border;
  if constexpr (kFieldNormals<Normals>) {
    for (int p = 0; p < kPixels; ++p)
      inside[p] = p % kTile < work.w && p / kTile < work.h ? 1.0f : 0.0f;
    insideRows.update(inside);
    border.begin(work, Clipped);
  }
  alignas(32) float centreX[kTile];
  for (int x = 0; x < kTile; ++x) centreX[x] = float(px0 + x) + 0.5f;
  LiveRows liveRows;
  liveRows.update(live);
  // The slab summed, the one composited before (in this pass or the one before).
  uint32_t current = UINT32_MAX, previous = state.previous;
  bool any = false;
  const auto finishSlab = [&]() {
    if (!any) {
      if (kFieldNormals<Normals>) border.clear();  // sums of kernels reaching the border alone
      return;
    }
    const Slab& slab = (*work.slabs)[current];
    const bool neighbour =
        previous != UINT32_MAX &&
        previous + (backToFront ? -1 : 1) == current &&  // no slab between them in this tile
        slabsAdjacent((*work.slabs)[previous], slab);
    const float zNear = float(slab.nearDepth), zFar = float(slab.farDepth);
    // Field normals: each pixel's mean value in the slab, for its neighbours.
    alignas(32) float mean[kFieldNormals<Normals> ? kPixels : 1];
    bool weighted[kFieldNormals<Normals> ? kPixels : 1];
    if constexpr (kFieldNormals<Normals>) {
      static_assert(Samples >= 2, "field normals are pre-integrated");
      for (int p = 0; p < kPixels; ++p) {
        // As the halves' sums add up (quarters: two a half).
        float sum = sv[0][p] + sv[1][p], weight = sw[0][p] + sw[1][p];
        if constexpr (Samples == 4) {
          sum += sv[2][p] + sv[3][p];
          weight += sw[2][p] + sw[3][p];
        }
        weighted[p] = weight > 0.0f;
        mean[p] = weighted[p] ? sum / weight : 0.0f;
      }
    }
    // The value at tile pixel (x, y) (the border's beyond the tile's sides); false: no kernel.
    const auto valueAt = [&](int x, int y, float& v) {
      if (x >= 0 && x < kTile && y >= 0 && y < kTile) {
        v = mean[y * kTile + x];
        return weighted[y * kTile + x];
      }
      const int side = y < 0 ? 0 : y >= kTile ? 1 : x < 0 ? 2 : 3;
      const int i = side < 2 ? x : y;
      const float w = border.weight[side][i];
      v = w > 0.0f ? border.sum[side][i] / w : 0.0f;
      return w > 0.0f;
    };
    for (int p = 0; p < kPixels; ++p) {
      float psv[Samples], psw[Samples], weight = 0.0f;
      for (int k = 0; k < Samples; ++k) {
        psv[k] = sv[k][p];
        psw[k] = sw[k][p];
        weight += psw[k];
        sv[k][p] = sw[k][p] = 0.0f;
      }
      glm::vec3 normal(0.0f);  // voxel normals' sum, or the field's gradient
      if constexpr (kVoxel) {
        normal = glm::vec3(sn[0][p], sn[1][p], sn[2][p]);
        sn[0][p] = sn[1][p] = sn[2][p] = 0.0f;
      }
      const bool had = hasLast[p];
      hasLast[p] = false;
      if (!(live[p] > 0.0f)) continue;
      if (weight > 0.0f) {
        const SlabSamples<Samples> samples =
            slabSamplesOf<Samples>(psv, psw, boxNear[p], boxFar[p], stretch[p], zNear, zFar);
        const int x = p % kTile, y = p / kTile;
        if constexpr (kFieldNormals<Normals>) {
          float right, left, up, down;
          const bool hasRight = valueAt(x + 1, y, right), hasLeft = valueAt(x - 1, y, left);
          const bool hasUp = valueAt(x, y + 1, up), hasDown = valueAt(x, y - 1, down);
          const float c = mean[p];
          const glm::vec2 derivatives(pixelDerivativeOf(hasRight, right, hasLeft, left, c, 1.0f),
                                      pixelDerivativeOf(hasUp, up, hasDown, down, c, 1.0f));
          // The halves' sums (quarters: two a half).
          const float frontSum = Samples == 2 ? psv[0] : psv[0] + psv[1];
          const float frontWeight = Samples == 2 ? psw[0] : psw[0] + psw[1];
          const float backSum = psv[Samples - 1] + (Samples == 2 ? 0.0f : psv[Samples - 2]);
          const float backWeight = psw[Samples - 1] + (Samples == 2 ? 0.0f : psw[Samples - 2]);
          normal = fieldGradientOf(derivatives, frontSum, frontWeight, backSum, backWeight, zNear,
                                   zFar, s.proj);
        }
        const glm::dvec2 centre(px0 + x + 0.5, py0 + y + 0.5);
        const glm::vec4 c =
            classifySlab<Samples>(samples, neighbour && had, last[p], backToFront, s.tables, zNear,
                                  zFar, SegmentLight<Normals>(s, centre, normal, toCamera));
        if (backToFront) {
          const float keep = 1.0f - c.a;
          image.r[p] = c.r + keep * image.r[p];
          image.g[p] = c.g + keep * image.g[p];
          image.b[p] = c.b + keep * image.b[p];
          image.a[p] = c.a + keep * image.a[p];
        } else {
          const float keep = 1.0f - image.a[p];
          image.r[p] += keep * c.r;
          image.g[p] += keep * c.g;
          image.b[p] += keep * c.b;
          image.a[p] += keep * c.a;
        }
        // The value the next slab's segments start from: this one's nearest to it.
        last[p] = samples.value[backToFront ? 0 : Samples - 1];
        hasLast[p] = true;
      }
      live[p] = image.a[p] < termination ? 1.0f : 0.0f;
    }
    if (kFieldNormals<Normals>) border.clear();
    liveRows.update(live);
    previous = current;
    any = false;
  };
  // The pixels that add a slab's kernels: those taking more slabs; field normals, all.
  const float* adding = kFieldNormals<Normals> ? inside : live;
  const LiveRows& addingRows = kFieldNormals<Normals> ? insideRows : liveRows;
  forEachTileItem(work, backToFront, [&](const TileCompositor::Item& item) {
    if (item.slab != current) {
      finishSlab();
      if (!liveRows.any()) return false;
      current = item.slab;
    }
    const SplatRecord& rec = work.records[item.entry & SlabPartition::kIndexMask];
    int x0, y0, x1, y1;
    if (!tileBox(work, rec, x0, y0, x1, y1)) return true;
    const bool openNear = (item.entry & SlabPartition::kFirstSlab) != 0;
    const bool openFar = (item.entry & SlabPartition::kLastSlab) != 0;
    const Slab& slab = (*work.slabs)[item.slab];
    const float zNear = float(std::clamp(slab.nearDepth, -kClipUnbounded, kClipUnbounded));
    const float zFar = float(std::clamp(slab.farDepth, -kClipUnbounded, kClipUnbounded));
    float bounds[Samples + 1];
    sampleBounds<Samples>(zNear, zFar, openNear, openFar, bounds);
    const float value = rec.color.a;
    const float nx = rec.color.x, ny = rec.color.y, nz = rec.color.z;  // voxel normals
    const float qa = rec.conic.x, qb = rec.conic.y, qc = rec.conic.z, amplitude = rec.conic.w;
    const float cx = rec.box.x, mu0 = rec.depth.x;
    const float slopeX = s.flatDepths ? 0.0f : rec.depth.y;
    const float slopeY = s.flatDepths ? 0.0f : rec.depth.z;
    const float toErf = 1.0f / (std::sqrt(2.0f) * rec.depth.w);
    const float b0 = bounds[0], b1 = bounds[std::min(1, Samples)];
    const float b2 = bounds[std::min(2, Samples)], b3 = bounds[std::min(3, Samples)];
    const float b4 = bounds[std::min(4, Samples)];
    // The kernel's weight in each sample at a pixel where its footprint's quadratic form is
    // `r` and its depth `mu`, the depths kept between `lo` and `hi` (Clipped), times `mask`:
    // the one formula of the tile's pixels and its border's.
    const auto weightsAt = [&](float r, float mu, float lo, float hi, float mask,
                               float(&d)[Samples]) __attribute__((always_inline)) {
      const float g =
          amplitude * halfScale * windowedGaussianOf(r < cutoff ? r : cutoff, cutoff) * mask;
      const auto erfAt = [&](float b) __attribute__((always_inline)) {
        // Values, not std::min's references: a select of addresses does not vectorize.
        if (Clipped) b = b < lo ? lo : b > hi ? hi : b;
        return profileErfOf((b - mu) * toErf, erfReach, Series);
      };
      const float e0 = erfAt(b0), e1 = erfAt(b1);
      d[0] = g * std::max(e1 - e0, 0.0f);
      if constexpr (Samples >= 2) {
        const float e2 = erfAt(b2);
        d[1] = g * std::max(e2 - e1, 0.0f);
        if constexpr (Samples >= 4) {
          const float e3 = erfAt(b3), e4 = erfAt(b4);
          d[2] = g * std::max(e3 - e2, 0.0f);
          d[3] = g * std::max(e4 - e3, 0.0f);
        }
      }
    };
    if constexpr (kFieldNormals<Normals>) {
      // The border pixels the kernel's box reaches add to their sums.
      int bx0, by0, bx1, by1;
      boxPixels(rec.box, s.width, s.height, bx0, by0, bx1, by1);
      for (int side = 0; side < TileBorder::kSides; ++side) {
        const int n = side < 2 ? work.w : work.h;
        for (int i = 0; i < n; ++i) {
          int x, y;
          TileBorder::pixel(work, side, i, x, y);
          if (x < bx0 || x > bx1 || y < by0 || y > by1) continue;
          const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - rec.box.y;
          const float r = qa * dx * dx + 2.0f * qb * dx * dy + qc * dy * dy;
          const float mu = (mu0 + slopeY * dy) + slopeX * dx;
          float d[Samples];
          weightsAt(r, mu, border.keptNear[side][i], border.keptFar[side][i], 1.0f, d);
          for (int k = 0; k < Samples; ++k) {
            border.weight[side][i] += d[k];
            border.sum[side][i] += value * d[k];
          }
        }
      }
      if (x0 > x1 || y0 > y1) return true;  // binned for the border alone
    }
    any = true;
    const uint32_t columns = LiveRows::columns(x0, x1);
    for (int y = y0; y <= y1; ++y) {
      if (!(addingRows.bits[y] & columns)) continue;
      const float dy = float(py0 + y) + 0.5f - rec.box.y;
      const float rowR = qc * dy * dy, rowMu = mu0 + slopeY * dy;
      // Every plane a restrict pointer of its own, the samples written out: the loop vectorizes.
      const auto addRun = [&](int first, auto n) __attribute__((always_inline)) {
        const int at = y * kTile + first;
        const auto plane = [&](float(*planes)[kStride], int k) {
          return planes[std::min(k, Samples - 1)] + at;
        };
        float* __restrict w0 = plane(sw, 0);
        float* __restrict w1 = plane(sw, 1);
        float* __restrict w2 = plane(sw, 2);
        float* __restrict w3 = plane(sw, 3);
        float* __restrict v0 = plane(sv, 0);
        float* __restrict v1 = plane(sv, 1);
        float* __restrict v2 = plane(sv, 2);
        float* __restrict v3 = plane(sv, 3);
        float* __restrict n0 = sn[0] + (kVoxel ? at : 0);
        float* __restrict n1 = sn[kVoxel ? 1 : 0] + (kVoxel ? at : 0);
        float* __restrict n2 = sn[kVoxel ? 2 : 0] + (kVoxel ? at : 0);
        const float* lv = adding + at;
        const float* kn = keptNear + at;
        const float* kf = keptFar + at;
        const float* xc = centreX + first;
        for (int i = 0; i < decltype(n)::value; ++i) {
          const int x = first + i;
          const float dx = xc[i] - cx;
          const float r = qa * dx * dx + 2.0f * qb * dx * dy + rowR;
          const float mu = rowMu + slopeX * dx;
          const bool take = (x >= x0) & (x <= x1) & (lv[i] > 0.0f);
          float d[Samples];
          weightsAt(r, mu, Clipped ? kn[i] : 0.0f, Clipped ? kf[i] : 0.0f, take ? 1.0f : 0.0f, d);
          w0[i] += d[0];
          v0[i] += value * d[0];
          if constexpr (Samples >= 2) {
            w1[i] += d[1];
            v1[i] += value * d[1];
            if constexpr (Samples >= 4) {
              w2[i] += d[2];
              v2[i] += value * d[2];
              w3[i] += d[3];
              v3[i] += value * d[3];
            }
          }
          if constexpr (kVoxel) {
            float total = 0.0f;  // the kernel's weight in the slab
            for (int k = 0; k < Samples; ++k) total += d[k];
            n0[i] += nx * total;
            n1[i] += ny * total;
            n2[i] += nz * total;
          }
        }
      };
      forRowRun(x0, x1, addRun);
    }
    return true;
  });
  finishSlab();
  state.previous = previous;
  state.done = !liveRows.any();
  std::copy_n(live, kPixels, state.live);
  storeTile(work, [&](int p) { return glm::vec4(image.r[p], image.g[p], image.b[p], image.a[p]); });
}

// X-ray (`Mip` false): each pixel's summed optical depth, every kernel whole (cut to the kept
// depths); MIP: the largest kernel-weighted value (no optical depth), as the splat fragments
// blend them into the one image of the whole volume.
template <bool Mip, bool Series, bool Clipped>
__attribute__((always_inline)) inline void wholeTileOf(const TileWork& work) {
  constexpr int kTile = TileCompositor::kTile;
  const TileCompositeSettings& s = *work.settings;
  const int px0 = work.px0, py0 = work.py0;
  const float cutoff = float(s.cutoff);
  const float erfReach = float(std::min(s.profile.erfReach, kClipUnbounded));
  const float halfScale = 0.5f * float(s.profile.scale);
  TileCompositor::TileState& state = *work.state;
  if (!state.begun) beginTile(work, Clipped, false);
  const float* keptNear = state.keptNear;
  const float* keptFar = state.keptFar;
  TilePlanes image;
  loadTile(work, image);
  alignas(32) float gathered[kPixels];
  for (int p = 0; p < kPixels; ++p) gathered[p] = Mip ? image.r[p] : image.a[p];
  alignas(32) float centreX[kTile];
  for (int x = 0; x < kTile; ++x) centreX[x] = float(px0 + x) + 0.5f;
  forEachTileItem(work, false, [&](const TileCompositor::Item& item) {
    const SplatRecord& rec = work.records[item.entry & SlabPartition::kIndexMask];
    int x0, y0, x1, y1;
    if (!tileBox(work, rec, x0, y0, x1, y1)) return true;
    const float scale = Mip ? rec.color.a : rec.conic.w;  // value, or optical depth at the centre
    const float qa = rec.conic.x, qb = rec.conic.y, qc = rec.conic.z;
    const float cx = rec.box.x, mu0 = rec.depth.x;
    const float slopeX = s.flatDepths ? 0.0f : rec.depth.y;
    const float slopeY = s.flatDepths ? 0.0f : rec.depth.z;
    const float toErf = 1.0f / (std::sqrt(2.0f) * rec.depth.w);
    for (int y = y0; y <= y1; ++y) {
      const float dy = float(py0 + y) + 0.5f - rec.box.y;
      const float rowR = qc * dy * dy, rowMu = mu0 + slopeY * dy;
      const auto addRun = [&](int first, auto n) __attribute__((always_inline)) {
        const int at = y * kTile + first;
        float* __restrict out = gathered + at;
        const float* kn = keptNear + at;
        const float* kf = keptFar + at;
        const float* xc = centreX + first;
        for (int i = 0; i < decltype(n)::value; ++i) {
          const int x = first + i;
          const float dx = xc[i] - cx;
          const float r = qa * dx * dx + 2.0f * qb * dx * dy + rowR;
          float share = 1.0f;  // uncut: the whole kernel
          if (Clipped) {
            const float mu = rowMu + slopeX * dx;
            share = kf[i] > kn[i]
                        ? slabShareOf(mu, toErf, kn[i], kf[i], erfReach, halfScale, Series)
                        : 0.0f;
          }
          const bool take = (x >= x0) & (x <= x1);
          const float c = scale * windowedGaussianOf(r < cutoff ? r : cutoff, cutoff) * share *
                          (take ? 1.0f : 0.0f);
          out[i] = Mip ? std::max(out[i], c) : out[i] + c;
        }
      };
      forRowRun(x0, x1, addRun);
    }
    return true;
  });
  storeTile(work, [&](int p) {
    const float g = gathered[p];
    return Mip ? glm::vec4(g, 0.0f, 0.0f, 0.0f) : glm::vec4(0.0f, 0.0f, 0.0f, g);
  });
}

// The post-classified tile for the frame's samples a slab.
template <bool Series, bool Clipped, TileNormals Normals>
inline void postTileWith(const TileWork& work) {
  const int samples = work.settings->samples;
  if (samples >= 4) {
    postTileOf<4, Series, Clipped, Normals>(work);
  } else if (samples == 2) {
    postTileOf<2, Series, Clipped, Normals>(work);
  } else if constexpr (Normals != TileNormals::Field) {  // field normals: pre-integrated only
    postTileOf<1, Series, Clipped, Normals>(work);
  }
}

// The tile's gather for the frame's settings: each variant's pixel loops compiled without the
// tests that pick it.
template <bool Series, bool Clipped>
inline void gatherTileWith(const TileWork& work) {
  const TileCompositeSettings& s = *work.settings;
  switch (s.gather) {
    case TileGather::Pre:
      compositeTileOf<Series, Clipped>(work);
      return;
    case TileGather::Post:
      if (s.normals == TileNormals::Voxel)
        postTileWith<Series, Clipped, TileNormals::Voxel>(work);
      else if (s.normals == TileNormals::Field)
        postTileWith<Series, Clipped, TileNormals::Field>(work);
      else if (s.normals == TileNormals::Ray)
        postTileWith<Series, Clipped, TileNormals::Ray>(work);
      else
        postTileWith<Series, Clipped, TileNormals::None>(work);
      return;
    case TileGather::XRay:
      wholeTileOf<false, Series, Clipped>(work);
      return;
    case TileGather::Mip:
      wholeTileOf<true, Series, Clipped>(work);
      return;
  }
}

inline void gatherTileFor(const TileWork& work, bool series, bool clipped) {
  if (series)
    clipped ? gatherTileWith<true, true>(work) : gatherTileWith<true, false>(work);
  else
    clipped ? gatherTileWith<false, true>(work) : gatherTileWith<false, false>(work);
}

}  // namespace ewa::tile_kernel::EWA_TILE_ISA
