// The shear-warp renderer's view of a volume: scalars as table coordinates, one slice-ordered
// copy per principal axis, and run-length encodings of transparent cells per axis.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/volume.h"

namespace ewa {

// Runs of non-transparent cells along the rows of each slice of one principal axis. Cell
// (i, j) of slice entry k spans voxels i..i+1, j..j+1 of slices k..k+1 (clamped at the last
// slice); `dilated` runs widen that by one voxel on every side, which covers a slab's back
// sample, displaced by at most one voxel per slice.
struct CellRuns {
  int rows = 0;                  // cell rows per slice (height - 1, at least 0)
  std::vector<int32_t> offsets;  // runs of (k, j) are [offsets[k*rows+j], offsets[...+1])
  std::vector<std::array<int32_t, 2>> runs;  // [first, last) cell i
  const std::array<int32_t, 2>* begin(int k, int j) const {
    return runs.data() + offsets[size_t(k) * rows + j];
  }
  const std::array<int32_t, 2>* end(int k, int j) const {
    return runs.data() + offsets[size_t(k) * rows + j + 1];
  }
};

class ShearWarpVolume {
 public:
  // Maps every scalar to its table coordinate (v - lo) / (hi - lo) * (tableSize - 1), clamped
  // to [0, tableSize - 1] (NaN to 0), and finds each cell's coordinate range.
  // tableSize must lie in [2, 256].
  void setVolume(const Volume& volume, double lo, double hi, int tableSize);
  // visibleBins[m] != 0 when the transfer function is not transparent somewhere in table
  // interval [m, m + 1]; tableSize - 1 entries. Drops the run-length encodings.
  void setVisibility(const std::vector<uint8_t>& visibleBins);

  bool empty() const { return voxels_ == 0; }
  const std::array<int64_t, 3>& dims() const { return dims_; }
  // Scalars of principal axis p in slice order: index (k * height + j) * width + i with i, j
  // along the axes (p+1)%3, (p+2)%3. Built on first use; not thread-safe.
  const std::vector<float>& slices(int principal);
  // Run-length encoding of non-transparent cells for principal axis p (built on first use after
  // setVisibility; not thread-safe). Without visibility every cell is one run.
  const CellRuns& runs(int principal, bool dilated);
  // Cells (of the undilated kind) that are not transparent, of all cells; for statistics.
  double visibleFraction() const { return visibleFraction_; }

 private:
  std::vector<uint8_t> cellVisibility(bool dilated) const;

  std::array<int64_t, 3> dims_{0, 0, 0};
  int64_t voxels_ = 0;
  int tableSize_ = 256;
  std::vector<float> coords_;             // x-fastest table coordinates
  std::vector<uint8_t> cellLo_, cellHi_;  // floor/ceil of each cell's coordinate range
  std::vector<uint8_t> wideLo_, wideHi_;  // the same, one voxel wider on every side
  std::vector<uint32_t> visiblePrefix_;   // prefix counts of visible bins; empty: all
  std::array<std::vector<float>, 3> slices_;
  std::array<std::array<CellRuns, 2>, 3> runs_;
  std::array<std::array<bool, 2>, 3> runsBuilt_{};
  double visibleFraction_ = 1.0;
};

}  // namespace ewa
