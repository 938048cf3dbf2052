// Compositing loops: standard slices and pre-integrated slabs with SB or IB buffer slices.
#include "core/shear_warp_compositor.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "core/shear_warp_perspective.h"
#include "core/shear_warp_samples.h"

namespace ewa {

namespace {

// Integer shift and bilinear weights of one slice in the intermediate image: intermediate
// pixel u samples the slice at cell u - shift, fraction `frac` towards the next voxel.
struct SlicePlacement {
  int shiftI, shiftJ;
  float fracI, fracJ;
  float w00, w10, w01, w11;

  SlicePlacement(const ShearWarpFactorization& f, int k) {
    const double oi = f.offsetI(k), oj = f.offsetJ(k);
    shiftI = int(std::ceil(oi));
    shiftJ = int(std::ceil(oj));
    fracI = float(shiftI - oi);
    fracJ = float(shiftJ - oj);
    w00 = (1.0f - fracI) * (1.0f - fracJ);
    w10 = fracI * (1.0f - fracJ);
    w01 = (1.0f - fracI) * fracJ;
    w11 = fracI * fracJ;
  }
  float sample(const float* row0, const float* row1, int i) const {
    return w00 * row0[i] + w10 * row0[i + 1] + w01 * row1[i] + w11 * row1[i + 1];
  }
};

// Cells [first, last) of a slice row whose samples the crop box and clipping planes keep.
struct CellRange {
  int first, last;
};

CellRange keptCells(const CompositeInput& in, int k, int j, const SlicePlacement& place) {
  CellRange r{0, in.view->width};
  if (in.clip && in.clip->active())
    in.clip->keptCells(k, j, place.fracI, place.fracJ, &r.first, &r.last);
  return r;
}

void compositeStandard(const CompositeInput& in, IntermediateImage& out, int thread, int threads) {
  const ShearWarpFactorization& f = *in.view;
  const size_t sliceSize = size_t(f.width) * f.height;
  const float threshold = float(in.settings.terminationAlpha);
  const float top = float(in.tableSize - 1);
  for (int step = 0; step < f.sliceCount; ++step) {
    const int k = f.sliceAt(step);
    const SlicePlacement place(f, k);
    for (int v = thread; v < out.height; v += threads) {
      const int j = v - place.shiftJ;
      if (j < 0 || j >= f.height - 1) continue;
      const float* row0 = in.slices + k * sliceSize + size_t(j) * f.width;
      const float* row1 = row0 + f.width;
      glm::vec4* pixels = out.pixels.data() + size_t(v) * out.width;
      const OpaqueLinks links{in.links + size_t(v) * (out.width + 1)};
      const CellRange kept = keptCells(in, k, j, place);
      for (auto run = in.runs->begin(k, j); run != in.runs->end(k, j); ++run) {
        // Within the image too: a close-up's intermediate image holds only the picture's rays.
        const int end = std::min(std::min((*run)[1], kept.last) + place.shiftI, out.width);
        const int start = std::max(std::max((*run)[0], kept.first) + place.shiftI, 0);
        if (start >= end) continue;
        for (int u = links.find(start); u < end; u = links.find(u + 1)) {
          const int i = u - place.shiftI;
          glm::vec4& p = pixels[u];
          const float s = std::min(place.sample(row0, row1, i), top);
          under(p, in.pointTable[int(s + 0.5f)]);
          if (p.a >= threshold) links.terminate(u);
        }
      }
    }
  }
}

template <bool kBilinear, bool kImageBuffer>
void compositeSlabs(const CompositeInput& in, IntermediateImage& out, int thread, int threads,
                    CompositorBuffers& buffers) {
  const ShearWarpFactorization& f = *in.view;
  const size_t sliceSize = size_t(f.width) * f.height;
  const float threshold = float(in.settings.terminationAlpha);
  const int n = in.tableSize;
  const float top = float(n - 1);
  BufferedSample* image = buffers.image.data();
  for (int step = 0; step + 1 < f.sliceCount; ++step) {
    const int k = f.sliceAt(step), k2 = f.sliceAt(step + 1);
    const int slab = std::min(k, k2);
    const SlicePlacement front(f, k), back(f, k2);
    // SB: this thread's buffer of slice k (filled by the last slab) and the one for slice k2.
    BufferedSample* previous =
        kImageBuffer ? nullptr : buffers.slices[2 * thread + step % 2].data();
    BufferedSample* current =
        kImageBuffer ? nullptr : buffers.slices[2 * thread + (step + 1) % 2].data();
    for (int v = thread; v < out.height; v += threads) {
      const int j = v - front.shiftJ, j2 = v - back.shiftJ;
      if (j < 0 || j >= f.height - 1 || j2 < 0 || j2 >= f.height - 1) continue;
      const float* f0 = in.slices + k * sliceSize + size_t(j) * f.width;
      const float* f1 = f0 + f.width;
      const float* b0 = in.slices + k2 * sliceSize + size_t(j2) * f.width;
      const float* b1 = b0 + f.width;
      glm::vec4* pixels = out.pixels.data() + size_t(v) * out.width;
      BufferedSample* imageRow = kImageBuffer ? image + size_t(v) * out.width : nullptr;
      BufferedSample* previousRow = kImageBuffer ? nullptr : previous + size_t(j) * f.width;
      BufferedSample* currentRow = kImageBuffer ? nullptr : current + size_t(j2) * f.width;
      const OpaqueLinks links{in.links + size_t(v) * (out.width + 1)};
      // Clipped by the front sample's position: a slab is kept or dropped whole.
      const CellRange kept = keptCells(in, k, j, front);
      for (auto run = in.runs->begin(slab, j); run != in.runs->end(slab, j); ++run) {
        const int end = std::min(std::min((*run)[1], kept.last) + front.shiftI, out.width);
        const int start = std::max(std::max((*run)[0], kept.first) + front.shiftI, 0);
        if (start >= end) continue;
        for (int u = links.find(start); u < end; u = links.find(u + 1)) {
          const int i = u - front.shiftI;
          glm::vec4& p = pixels[u];
          const int i2 = u - back.shiftI;
          if (i2 < 0 || i2 >= f.width - 1) continue;
          BufferedSample& saved = kImageBuffer ? imageRow[u] : previousRow[i];
          const float sf = saved.slice == k ? saved.value : front.sample(f0, f1, i);
          const float sb = std::min(back.sample(b0, b1, i2), top);
          BufferedSample& next = kImageBuffer ? imageRow[u] : currentRow[i2];
          next.value = sb;
          next.slice = k2;
          under(p, lookupPair<kBilinear>(in.pairTable, n, std::min(sf, top), sb));
          if (p.a >= threshold) links.terminate(u);
        }
      }
    }
  }
}

void compositeRows(const CompositeInput& in, IntermediateImage& out, int thread, int threads,
                   CompositorBuffers& buffers) {
  const ShearWarpSettings& s = in.settings;
  if (in.view->resampled()) return compositePerspective(in, out, thread, threads, buffers);
  if (!s.preintegrated) return compositeStandard(in, out, thread, threads);
  const bool bilinear = s.lookup == TableLookup::Bilinear;
  const bool image = s.buffers == BufferSlices::Image;
  if (bilinear && image) return compositeSlabs<true, true>(in, out, thread, threads, buffers);
  if (bilinear) return compositeSlabs<true, false>(in, out, thread, threads, buffers);
  if (image) return compositeSlabs<false, true>(in, out, thread, threads, buffers);
  compositeSlabs<false, false>(in, out, thread, threads, buffers);
}

// Grows the buffers the settings need (never shrinks them) and marks every entry empty.
void prepareBuffers(const CompositeInput& in, int threads, const IntermediateImage& out,
                    CompositorBuffers& buffers) {
  if (!in.settings.preintegrated) return;
  const BufferedSample empty;
  // Resampled views buffer by intermediate pixel: a ray's back sample is the next slab's front.
  if (in.settings.buffers == BufferSlices::Image || in.view->resampled()) {
    const size_t size = size_t(out.width) * out.height;
    if (buffers.image.size() < size) buffers.image.resize(size);
    std::fill(buffers.image.begin(), buffers.image.begin() + size, empty);
    return;
  }
  const size_t size = size_t(in.view->width) * in.view->height;
  if (buffers.slices.size() < size_t(2 * threads)) buffers.slices.resize(2 * threads);
  for (auto& b : buffers.slices) {
    if (b.size() < size) b.resize(size);
    std::fill(b.begin(), b.begin() + size, empty);
  }
}

}  // namespace

void compositeSlices(const CompositeInput& input, int threads, CompositorBuffers& buffers,
                     IntermediateImage& out) {
  const ShearWarpFactorization& f = *input.view;
  out.reset(f.imageWidth, f.imageHeight);
  if (f.width < 2 || f.height < 2 || f.sliceCount < 1 || !input.slices || !input.runs) return;
  threads = std::clamp(threads, 1, std::max(1, out.height));
  prepareBuffers(input, threads, out, buffers);
  // One link array per row, width + 1 entries (the last one never terminates).
  const size_t rowLinks = size_t(out.width) + 1;
  buffers.links.resize(rowLinks * out.height);
  for (size_t r = 0; r < size_t(out.height); ++r)
    for (size_t u = 0; u < rowLinks; ++u) buffers.links[r * rowLinks + u] = int32_t(u);
  CompositeInput in = input;
  in.links = buffers.links.data();
  if (f.perspective && input.settings.opacityCorrection && input.tableLog) {
    // Each ray's ratio once a frame, not once a sample.
    buffers.rayRatios.resize(size_t(out.width) * out.height);
    for (int v = 0; v < out.height; ++v)
      for (int u = 0; u < out.width; ++u)
        buffers.rayRatios[size_t(v) * out.width + u] = float(f.rayRatio(u, v));
    in.rayRatios = buffers.rayRatios.data();
  }
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back(compositeRows, std::cref(in), std::ref(out), t, threads, std::ref(buffers));
  compositeRows(in, out, 0, threads, buffers);
  for (std::thread& th : pool) th.join();
}

}  // namespace ewa
