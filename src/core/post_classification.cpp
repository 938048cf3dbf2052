// The voxels post-classified splatting keeps: visible ones, crossings and a dilated margin.
#include "core/post_classification.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/named_values.h"
#include "core/parallel_chunks.h"

namespace ewa {

namespace {

constexpr int kTable = 4096;
constexpr int kMaxMarginSquared = 225;  // 15 voxels: squared distances stay within a byte

// One pass of a windowed squared-distance transform along an axis of a grid holding squared
// distances capped at `cap`: each entry becomes min over |s| <= margin of the entry s along the
// axis plus s^2. Three passes (x, y, z) from seeds 0 and the rest `cap` give the squared
// Euclidean distance to the nearest seed wherever it is at most margin^2 (every axis offset of
// such a seed is within the window).
//
// Along x the lines are contiguous. Along y and z the pass runs over whole contiguous rows
// (x-rows, or xy-planes for z), row t taking the minimum over rows t - margin ... t + margin, so
// memory is read in order: gathering a z-line one byte a plane apart missed the cache at every
// voxel. Rows before t are overwritten by then; their values before the pass are kept in `past`.
void distanceX(std::vector<uint8_t>& grid, const std::array<int64_t, 3>& d, int margin, int cap,
               unsigned threads) {
  const int64_t n = d[0];
  if (n <= 1) return;
  const size_t rows = grid.size() / size_t(n);
  parallelChunks(rows, minItemsPerChunk(size_t(n)), threads,
                 [&](size_t first, size_t last, size_t) {
                   std::vector<uint8_t> line(static_cast<size_t>(n));
                   for (size_t r = first; r < last; ++r) {
                     uint8_t* row = grid.data() + r * size_t(n);
                     if (std::all_of(row, row + n, [cap](uint8_t v) { return v >= cap; })) continue;
                     std::copy(row, row + n, line.begin());
                     for (int64_t t = 0; t < n; ++t) {
                       int best = line[size_t(t)];
                       const int64_t lo = std::max<int64_t>(t - margin, 0),
                                     hi = std::min<int64_t>(t + margin, n - 1);
                       for (int64_t u = lo; u <= hi; ++u)
                         best = std::min(best, line[size_t(u)] + int((u - t) * (u - t)));
                       row[t] = uint8_t(std::min(best, cap));
                     }
                   }
                 });
}

// distanceRows over blocks [o0, o1) and, in each row, the bytes [x0, x1).
void distanceRowsPart(std::vector<uint8_t>& grid, int64_t length, int64_t count, int64_t o0,
                      int64_t o1, size_t x0, size_t x1, int margin, int cap) {
  const size_t len = size_t(length), part = x1 - x0;
  std::vector<uint8_t> past(size_t(margin) * part), original(part);
  std::vector<int> best(part);
  for (int64_t o = o0; o < o1; ++o) {
    uint8_t* block = grid.data() + size_t(o * count) * len + x0;
    for (int64_t t = 0; t < count; ++t) {
      uint8_t* row = block + size_t(t) * len;
      std::copy(row, row + part, original.begin());
      for (size_t x = 0; x < part; ++x) best[x] = row[x];
      for (int s = 1; s <= margin; ++s) {
        const int add = s * s;
        if (t - s >= 0) {  // before the pass: kept in past, slot (t - s) % margin
          const uint8_t* before = past.data() + size_t((t - s) % margin) * part;
          for (size_t x = 0; x < part; ++x) best[x] = std::min(best[x], before[x] + add);
        }
        if (t + s < count) {
          const uint8_t* after = block + size_t(t + s) * len;
          for (size_t x = 0; x < part; ++x) best[x] = std::min(best[x], after[x] + add);
        }
      }
      for (size_t x = 0; x < part; ++x) row[x] = uint8_t(std::min(best[x], cap));
      std::copy(original.begin(), original.end(), past.begin() + size_t(t % margin) * part);
    }
  }
}

// `rows` rows of `length` bytes, `count` of them along the axis, repeated `outer` times. The
// blocks, or with one block the columns of bytes, are independent: split between the cores.
void distanceRows(std::vector<uint8_t>& grid, int64_t length, int64_t count, int64_t outer,
                  int margin, int cap, unsigned threads) {
  if (count <= 1) return;
  if (outer > 1) {
    parallelChunks(size_t(outer), minItemsPerChunk(size_t(length * count)), threads,
                   [&](size_t first, size_t last, size_t) {
                     distanceRowsPart(grid, length, count, int64_t(first), int64_t(last), 0,
                                      size_t(length), margin, cap);
                   });
  } else {
    parallelChunks(size_t(length), minItemsPerChunk(size_t(count)), threads,
                   [&](size_t first, size_t last, size_t) {
                     distanceRowsPart(grid, length, count, 0, outer, first, last, margin, cap);
                   });
  }
}

// Keeps the voxels within squared Euclidean distance `marginSquared` (in voxel steps) of a set
// one: a ball, as a kernel reaches, not the cube of a per-axis max filter, whose corners reach
// sqrt(3) times as far and, around thin structures, hold most of the margin.
void dilateBall(std::vector<uint8_t>& mask, const std::array<int64_t, 3>& d, int marginSquared,
                unsigned threads) {
  const int r2 = std::clamp(marginSquared, 0, kMaxMarginSquared);  // r2 + 1 fits a byte
  if (r2 == 0) return;
  // Every axis offset of a voxel within the ball is at most the whole part of its radius.
  const int m = int(std::sqrt(double(r2)) + 1e-9);
  const int cap = r2 + 1;
  auto map = [&](auto f) {
    parallelChunks(mask.size(), kMinChunkWork * 16, threads,
                   [&](size_t first, size_t last, size_t) {
                     for (size_t n = first; n < last; ++n) mask[n] = f(mask[n]);
                   });
  };
  map([cap](uint8_t v) { return v ? uint8_t(0) : uint8_t(cap); });
  distanceX(mask, d, m, cap, threads);
  distanceRows(mask, d[0], d[1], d[2], m, cap, threads);
  distanceRows(mask, d[0] * d[1], d[2], 1, m, cap, threads);
  map([cap](uint8_t v) { return uint8_t(v < cap ? 1 : 0); });
}

// A value's place in the 4096-entry table: the entries below and above it (equal on an entry);
// floor kTable marks a NaN or infinite value.
struct TablePosition {
  uint16_t floor = kTable;
  uint16_t ceil = kTable;
  bool finite() const { return floor < kTable; }
};

// The table positions of slice k (x fastest), into `at`.
void slicePositions(const Volume& volume, int64_t k, double lo, double width,
                    std::vector<TablePosition>* at) {
  const int64_t first = volume.index(0, 0, k);
  for (size_t n = 0; n < at->size(); ++n) {
    const double v = volume.valueAt(first + int64_t(n));
    TablePosition& p = (*at)[n];
    p = TablePosition();
    if (!std::isfinite(v)) continue;
    const double x = std::clamp((v - lo) / width, 0.0, 1.0) * (kTable - 1);
    p.floor = uint16_t(std::floor(x));
    p.ceil = uint16_t(std::ceil(x));
  }
}

constexpr NamedValue<ClassificationMode> kClassificationModeNames[] = {
    {ClassificationMode::Pre, "pre"}, {ClassificationMode::Post, "post"}};
}  // namespace

const char* classificationModeName(ClassificationMode mode) {
  return nameIn(kClassificationModeNames, mode);
}

bool parseClassificationMode(const std::string& text, ClassificationMode* mode) {
  return parseIn(kClassificationModeNames, text, mode);
}

std::vector<std::string> classificationModeNames() {
  return namesIn(kClassificationModeNames);
}

int postClassificationMarginSquared(double cutoff, double kernelWidth) {
  // Every voxel whose centre lies within a kernel's reach of a visible voxel's centre (reach^2 =
  // cutoff * width^2, in voxel steps): wherever a visible kernel reaches, the voxels it shares
  // the point with are then nearly all splatted, so the weighted mean there is the
  // reconstructed value, not one pulled toward the visible voxels' values, which swells thin
  // structures. At width 0.7, cutoff 5 (reach^2 2.45) that keeps the 18 voxels of squared
  // distance 1 and 2; whole voxels of reach (the 6 face neighbours) left close-ups further from
  // VTK's ray caster (lidc2 0.958 -> 0.980, aneurism 0.982 -> 0.987 at one view each:
  // docs/rendering.md, A margin as far as a kernel reaches).
  const double reach2 = std::max(cutoff, 0.0) * std::max(kernelWidth, 0.0) * kernelWidth;
  return std::clamp(int(std::floor(reach2 + 1e-9)), 1, kMaxMarginSquared);
}

std::vector<uint8_t> postClassificationMask(const Volume& volume,
                                            const std::function<bool(double)>& isVisible,
                                            int marginSquared, unsigned threads) {
  const auto& d = volume.dims();
  std::vector<uint8_t> mask(size_t(volume.voxelCount()), 0);
  if (mask.empty()) return mask;
  const double lo = volume.minValue(), hi = volume.maxValue();
  const double width = hi > lo ? hi - lo : 1.0;
  // Visible table entries counted from the front: a value interval has a visible value where
  // the count grows across it.
  std::vector<int> before(kTable + 1, 0);
  for (int t = 0; t < kTable; ++t)
    before[t + 1] = before[t] + (isVisible(lo + width * t / (kTable - 1)) ? 1 : 0);
  if (before[kTable] == 0) return mask;
  // Each voxel's table position as its floor and ceiling entries, computed once per voxel and
  // slice (for the slices before and after, the neighbours' along z): the interval between two
  // values reaches from the lower floor to the higher ceiling (floor and ceiling are
  // monotonic), so the tests below are integer work only.
  const size_t sliceSize = size_t(d[0] * d[1]);
  auto anyVisible = [&](TablePosition a, TablePosition b) {
    return before[std::max(a.ceil, b.ceil) + 1] - before[std::min(a.floor, b.floor)] > 0;
  };
  // Each voxel decides its own mark from its neighbours (no voxel writes another's), so runs of
  // slices go to the machine's cores.
  parallelChunks(
      size_t(d[2]), minItemsPerChunk(sliceSize), threads, [&](size_t first, size_t last, size_t) {
        std::vector<TablePosition> prev(sliceSize), here(sliceSize), next(sliceSize);
        if (first > 0) slicePositions(volume, int64_t(first) - 1, lo, width, &prev);
        slicePositions(volume, int64_t(first), lo, width, &here);
        for (int64_t k = int64_t(first); k < int64_t(last); ++k) {
          if (k + 1 < d[2]) slicePositions(volume, k + 1, lo, width, &next);
          for (int64_t j = 0; j < d[1]; ++j)
            for (int64_t i = 0; i < d[0]; ++i) {
              const int64_t m = i + d[0] * j;  // in the slice
              const TablePosition v = here[size_t(m)];
              if (!v.finite()) continue;
              // A crossing between two invisible values marks both (a visible end is a seed
              // itself, and the margin covers its neighbours).
              auto crossing = [&](TablePosition w) {
                return w.finite() && !anyVisible(w, w) && anyVisible(v, w);
              };
              const bool seed = anyVisible(v, v) || (i > 0 && crossing(here[size_t(m - 1)])) ||
                                (i + 1 < d[0] && crossing(here[size_t(m + 1)])) ||
                                (j > 0 && crossing(here[size_t(m - d[0])])) ||
                                (j + 1 < d[1] && crossing(here[size_t(m + d[0])])) ||
                                (k > 0 && crossing(prev[size_t(m)])) ||
                                (k + 1 < d[2] && crossing(next[size_t(m)]));
              if (seed) mask[size_t(volume.index(i, j, k))] = 1;
            }
          prev.swap(here);
          here.swap(next);
        }
      });
  dilateBall(mask, d, marginSquared, threads);
  return mask;
}

}  // namespace ewa
