// exchangeGhosts under mpirun: every rank's region put together from its neighbours' bricks
// equals the whole volume cut to that region, voxel for voxel, for 16-bit and float volumes,
// ghosts of 0 to 5 voxels and a split with more ranks than a thin axis has voxels; exit 0 when
// all hold.
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/volume_crop.h"
#include "dist/brick_split.h"
#include "dist/mpi_ghost_exchange.h"

namespace {

int failures = 0;
int rank = 0;

void check(bool ok, const std::string& what) {
  if (ok) return;
  ++failures;
  std::fprintf(stderr, "rank %d: FAILED: %s\n", rank, what.c_str());
}

// A volume whose every voxel differs from the others (its index as the value).
ewa::Volume numbered(std::array<int64_t, 3> dims, ewa::ScalarType type) {
  const size_t n = size_t(dims[0] * dims[1] * dims[2]);
  std::vector<uint8_t> bytes(n * ewa::scalarSize(type));
  for (size_t v = 0; v < n; ++v) {
    if (type == ewa::ScalarType::Float32) {
      const float f = float(v) * 0.5f;
      std::memcpy(bytes.data() + v * 4, &f, 4);
    } else {
      const uint16_t u = uint16_t(v * 7u);
      std::memcpy(bytes.data() + v * 2, &u, 2);
    }
  }
  ewa::Volume volume(dims, {1.0, 2.0, 0.5}, {3.0, -1.0, 4.0}, type, std::move(bytes));
  return volume;
}

ewa::VoxelRange rangeOf(const std::array<int64_t, 3>& lo, const std::array<int64_t, 3>& hi) {
  ewa::VoxelRange r;
  for (size_t a = 0; a < 3; ++a) r.low[a] = lo[a], r.high[a] = hi[a] - 1;
  return r;
}

void checkExchange(std::array<int64_t, 3> dims, ewa::ScalarType type, int64_t ghost, int size) {
  const std::string what = std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                           std::to_string(dims[2]) + " ghost " + std::to_string(ghost);
  const ewa::Volume whole = numbered(dims, type);
  const ewa::dist::BrickSplit split = ewa::dist::splitBricks(ewa::dist::VoxelWeights(dims), size);
  std::vector<ewa::VoxelRegion> regions(static_cast<size_t>(size));
  for (int r = 0; r < size; ++r)
    for (size_t a = 0; a < 3; ++a) {
      regions[size_t(r)].lo[a] = std::max<int64_t>(split.bricks[size_t(r)].low[a] - ghost, 0);
      regions[size_t(r)].hi[a] =
          std::min<int64_t>(split.bricks[size_t(r)].high[a] + ghost, dims[a]);
    }
  const ewa::dist::VoxelBox& brick = split.bricks[size_t(rank)];
  ewa::Volume own;
  if (!brick.empty()) own = ewa::cropVolume(whole, rangeOf(brick.low, brick.high));
  const ewa::Volume got = ewa::dist::exchangeGhosts(own, split.bricks, regions, MPI_COMM_WORLD);
  if (brick.empty()) {
    check(got.empty(), what + ": an empty brick gets no region");
    return;
  }
  const ewa::VoxelRegion& region = regions[size_t(rank)];
  const ewa::Volume want = ewa::cropVolume(whole, rangeOf(region.lo, region.hi));
  check(got.dims() == want.dims(), what + ": region dims");
  check(got.bytes() == want.bytes(), what + ": region voxels");
  check(got.origin() == want.origin(), what + ": region origin");
  check(got.type() == whole.type(), what + ": value type");
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  try {
    for (int64_t ghost : {0, 1, 5}) {
      checkExchange({23, 17, 11}, ewa::ScalarType::UInt16, ghost, size);
      checkExchange({9, 30, 14}, ewa::ScalarType::Float32, ghost, size);
    }
    // Fewer voxels along the split axes than ranks: some bricks are empty.
    checkExchange({2, 1, 1}, ewa::ScalarType::Float32, 2, size);
  } catch (const std::exception& e) {
    check(false, e.what());
  }
  int all = 0;
  MPI_Allreduce(&failures, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) std::printf("ghost exchange on %d ranks: %d failures\n", size, all);
  MPI_Finalize();
  return all == 0 ? 0 : 1;
}
