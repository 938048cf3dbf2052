// Perspective shear-warp compositing: slices scaled towards the eye, one ray per pixel.
#include "core/shear_warp_perspective.h"

#include <algorithm>
#include <cmath>

#include "core/shear_warp_samples.h"

namespace ewa {

namespace {

// Where row v of the intermediate image meets slice k: the slice row j and the fraction fy
// towards row j + 1, and the map u -> x = (u - offset) / scale along the row.
struct RowPlacement {
  double scale, offsetI, inverseScale;
  int j = -1;
  float fy = 0.0f;
  double y = 0.0;

  RowPlacement(const ShearWarpFactorization& f, int k, int v)
      : scale(f.scale(k)), offsetI(f.offsetI(k)), inverseScale(1.0 / scale) {
    y = (v - f.offsetJ(k)) / scale;
    const double fl = std::floor(y);
    if (fl >= 0.0 && fl < f.height - 1) {
      j = int(fl);
      fy = float(y - fl);
    }
  }
  bool valid() const { return j >= 0; }
  double x(int u) const { return (u - offsetI) * inverseScale; }  // a division cost a tenth
  // The first intermediate pixel whose x is at least `at`, clamped to [0, width] (in doubles:
  // slices near the eye are scaled far past an int).
  int firstU(double at, int width) const {
    return int(std::clamp(std::ceil(at * scale + offsetI), 0.0, double(width)));
  }
  // The bilinear sample at u of the rows `row0` and `row1` (cells [a, b) of the row, which x
  // lies in but for rounding).
  float sample(const float* row0, const float* row1, int u, int a, int b) const {
    const double xu = x(u);
    const int i = std::clamp(int(std::floor(xu)), a, b - 1);
    const float fx = float(std::clamp(xu - i, 0.0, 1.0));
    return (1.0f - fy) * ((1.0f - fx) * row0[i] + fx * row0[i + 1]) +
           fy * ((1.0f - fx) * row1[i] + fx * row1[i + 1]);
  }
};

// The cells [*a, *b) of a run narrowed to the positions the crop box and planes keep, as the
// intermediate pixels [*u0, *u1) of a row `width` wide that sample them; false when none is.
bool runPixels(const CompositeInput& in, int k, const RowPlacement& row, int a, int b, int width,
               int* u0, int* u1) {
  double lo = a, hi = b;
  if (in.clip && in.clip->active()) {
    double keptLo = -1e300, keptHi = 1e300;
    in.clip->keptSpan(k, row.y, &keptLo, &keptHi);
    lo = std::max(lo, keptLo);
    hi = std::min(hi, std::nextafter(keptHi, 1e300));
  }
  if (!(lo < hi)) return false;
  *u0 = row.firstU(lo, width);
  *u1 = row.firstU(hi, width);
  return *u0 < *u1;
}

// correctPremultiplied for the ray through (u, v), in floats, from ln(1 - alpha) of the sample
// (`logT`; the table's, read beside its entry), without a log or, mostly, an exp a sample (two
// thirds of a frame went to the doubles' log1p and expm1).
inline glm::vec4 corrected(const glm::vec4& sample, float logT, const CompositeInput& in, int u,
                           int v, int width) {
  if (!in.rayRatios || sample.a <= 0.0f || sample.a >= 1.0f) return sample;
  // 1 - alpha' = (1 - alpha) exp(x), x = (ratio - 1) ln(1 - alpha) <= 0: near 0 for most rays
  // and samples, where four terms of the series are within 3e-4 of exp (and cost a tenth).
  const float x = (in.rayRatios[size_t(v) * width + u] - 1.0f) * logT;
  const float e = x > -0.5f
                      ? 1.0f + x * (1.0f + x * (0.5f + x * (1.0f / 6.0f + x * (1.0f / 24.0f))))
                      : std::exp(x);
  const float alpha = 1.0f - (1.0f - sample.a) * e;
  return glm::vec4(glm::vec3(sample) * (alpha / sample.a), alpha);
}

void compositeStandard(const CompositeInput& in, IntermediateImage& out, int thread, int threads) {
  const ShearWarpFactorization& f = *in.view;
  const size_t sliceSize = size_t(f.width) * f.height;
  const float threshold = float(in.settings.terminationAlpha);
  const float top = float(in.tableSize - 1);
  for (int step = 0; step < f.sliceCount; ++step) {
    const int k = f.sliceAt(step);
    for (int v = thread; v < out.height; v += threads) {
      const RowPlacement row(f, k, v);
      if (!row.valid()) continue;
      const float* row0 = in.slices + k * sliceSize + size_t(row.j) * f.width;
      const float* row1 = row0 + f.width;
      glm::vec4* pixels = out.pixels.data() + size_t(v) * out.width;
      const OpaqueLinks links{in.links + size_t(v) * (out.width + 1)};
      for (auto run = in.runs->begin(k, row.j); run != in.runs->end(k, row.j); ++run) {
        int start, end;
        if (!runPixels(in, k, row, (*run)[0], (*run)[1], out.width, &start, &end)) continue;
        for (int u = links.find(start); u < end; u = links.find(u + 1)) {
          glm::vec4& p = pixels[u];
          const float s = std::min(row.sample(row0, row1, u, (*run)[0], (*run)[1]), top);
          const int e = int(s + 0.5f);
          under(p, corrected(in.pointTable[e], in.rayRatios ? in.tableLog[e] : 0.0f, in, u, v,
                             out.width));
          if (p.a >= threshold) links.terminate(u);
        }
      }
    }
  }
}

template <bool kBilinear>
void compositeSlabs(const CompositeInput& in, IntermediateImage& out, int thread, int threads,
                    CompositorBuffers& buffers) {
  const ShearWarpFactorization& f = *in.view;
  const size_t sliceSize = size_t(f.width) * f.height;
  const float threshold = float(in.settings.terminationAlpha);
  const int n = in.tableSize;
  const float top = float(n - 1);
  for (int step = 0; step + 1 < f.sliceCount; ++step) {
    const int k = f.sliceAt(step), k2 = f.sliceAt(step + 1);
    const int slab = std::min(k, k2);
    for (int v = thread; v < out.height; v += threads) {
      const RowPlacement front(f, k, v), back(f, k2, v);
      if (!front.valid() || !back.valid()) continue;
      const float* f0 = in.slices + k * sliceSize + size_t(front.j) * f.width;
      const float* f1 = f0 + f.width;
      const float* b0 = in.slices + k2 * sliceSize + size_t(back.j) * f.width;
      const float* b1 = b0 + f.width;
      glm::vec4* pixels = out.pixels.data() + size_t(v) * out.width;
      BufferedSample* saved = buffers.image.data() + size_t(v) * out.width;
      const OpaqueLinks links{in.links + size_t(v) * (out.width + 1)};
      // Dilated runs of the front sample's row hold the back sample too (a ray moves less than
      // a voxel across per slice within 45 degrees of the principal axis).
      for (auto run = in.runs->begin(slab, front.j); run != in.runs->end(slab, front.j); ++run) {
        int start, end;
        if (!runPixels(in, k, front, (*run)[0], (*run)[1], out.width, &start, &end)) continue;
        for (int u = links.find(start); u < end; u = links.find(u + 1)) {
          const double x2 = back.x(u);
          if (!(x2 >= 0.0 && x2 <= f.width - 1)) continue;
          BufferedSample& s = saved[u];
          const float sf = s.slice == k ? s.value : front.sample(f0, f1, u, (*run)[0], (*run)[1]);
          const float sb = std::min(back.sample(b0, b1, u, 0, f.width - 1), top);
          s.value = sb;
          s.slice = k2;
          glm::vec4& p = pixels[u];
          const float ahead = std::min(sf, top);
          const glm::vec4 pair = lookupPair<kBilinear>(in.pairTable, n, ahead, sb);
          // Bilinear lookups blend entries: the blend's own ln(1 - alpha).
          const float logT = !in.rayRatios ? 0.0f
                             : kBilinear   ? (pair.a < 1.0f ? std::log1p(-pair.a) : -INFINITY)
                                           : in.tableLog[nearestPair(n, ahead, sb)];
          under(p, corrected(pair, logT, in, u, v, out.width));
          if (p.a >= threshold) links.terminate(u);
        }
      }
    }
  }
}

}  // namespace

void compositePerspective(const CompositeInput& in, IntermediateImage& out, int thread, int threads,
                          CompositorBuffers& buffers) {
  if (!in.settings.preintegrated) return compositeStandard(in, out, thread, threads);
  if (in.settings.lookup == TableLookup::Bilinear)
    return compositeSlabs<true>(in, out, thread, threads, buffers);
  compositeSlabs<false>(in, out, thread, threads, buffers);
}

}  // namespace ewa
