// exchangeGhosts: one MPI_Alltoallv of the bricks' parts that lie in the other ranks' regions.
#include "dist/mpi_ghost_exchange.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <stdexcept>
#include <string>

namespace ewa::dist {

namespace {

// The voxels both `brick` and `region` hold (empty: hi <= lo on some axis).
VoxelRegion overlap(const VoxelBox& brick, const VoxelRegion& region) {
  VoxelRegion o;
  for (size_t a = 0; a < 3; ++a) {
    o.lo[a] = std::max(brick.low[a], region.lo[a]);
    o.hi[a] = std::max(o.lo[a], std::min(brick.high[a], region.hi[a]));
  }
  return o;
}

int64_t voxelsOf(const VoxelRegion& r) {
  return (r.hi[0] - r.lo[0]) * (r.hi[1] - r.lo[1]) * (r.hi[2] - r.lo[2]);
}

// Copies the rows of `part` between two x-fastest boxes of voxels (whole-volume indices):
// `from` laid out over `fromBox`, `to` over `toBox`; null `to`/`from` are packed buffers of
// exactly `part`.
void copyRows(const uint8_t* from, const VoxelRegion* fromBox, uint8_t* to,
              const VoxelRegion* toBox, const VoxelRegion& part, size_t valueBytes) {
  const size_t row = size_t(part.hi[0] - part.lo[0]) * valueBytes;
  auto offset = [&](const VoxelRegion& box, int64_t j, int64_t k) {
    const int64_t nx = box.hi[0] - box.lo[0], ny = box.hi[1] - box.lo[1];
    return size_t(((k - box.lo[2]) * ny + (j - box.lo[1])) * nx + (part.lo[0] - box.lo[0])) *
           valueBytes;
  };
  size_t packed = 0;
  for (int64_t k = part.lo[2]; k < part.hi[2]; ++k)
    for (int64_t j = part.lo[1]; j < part.hi[1]; ++j, packed += row)
      std::memcpy(to + (toBox ? offset(*toBox, j, k) : packed),
                  from + (fromBox ? offset(*fromBox, j, k) : packed), row);
}

int countOf(int64_t bytes) {
  if (bytes > INT_MAX)
    throw std::invalid_argument("a ghost message of " + std::to_string(bytes) +
                                " bytes passes MPI's 2 GiB count");
  return int(bytes);
}

}  // namespace

Volume exchangeGhosts(const Volume& own, const std::vector<VoxelBox>& bricks,
                      const std::vector<VoxelRegion>& regions, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const VoxelBox& brick = bricks[size_t(rank)];
  VoxelRegion mine;
  for (size_t a = 0; a < 3; ++a) mine.lo[a] = brick.low[a], mine.hi[a] = brick.high[a];
  // Every rank agrees on the value type (an empty brick's own volume has none).
  int type = brick.empty() ? -1 : int(own.type()), common = -1;
  MPI_Allreduce(&type, &common, 1, MPI_INT, MPI_MAX, comm);
  const size_t valueBytes = common < 0 ? 1 : scalarSize(ScalarType(common));
  if (!brick.empty() && own.voxelCount() != brick.voxels())
    throw std::invalid_argument("the brick's volume holds " + std::to_string(own.voxelCount()) +
                                " voxels, its brick " + std::to_string(brick.voxels()));

  // What goes to each rank (its region's part of this brick) and comes from each (this
  // region's part of its brick), packed in rank order.
  std::vector<int> sendCounts(size_t(size), 0), sendOffsets(size_t(size), 0);
  std::vector<int> recvCounts(size_t(size), 0), recvOffsets(size_t(size), 0);
  int64_t sendTotal = 0, recvTotal = 0;
  for (int r = 0; r < size; ++r) {
    // An empty brick has no region to fill and no voxels to give.
    const bool both = r != rank && !brick.empty() && !bricks[size_t(r)].empty();
    const int64_t out = both ? voxelsOf(overlap(brick, regions[size_t(r)])) : 0;
    const int64_t in = both ? voxelsOf(overlap(bricks[size_t(r)], regions[size_t(rank)])) : 0;
    sendOffsets[size_t(r)] = countOf(sendTotal);
    recvOffsets[size_t(r)] = countOf(recvTotal);
    sendCounts[size_t(r)] = countOf(out * int64_t(valueBytes));
    recvCounts[size_t(r)] = countOf(in * int64_t(valueBytes));
    sendTotal += out * int64_t(valueBytes);
    recvTotal += in * int64_t(valueBytes);
  }
  countOf(sendTotal);
  countOf(recvTotal);
  std::vector<uint8_t> sent(static_cast<size_t>(sendTotal));
  std::vector<uint8_t> received(static_cast<size_t>(recvTotal));
  for (int r = 0; r < size; ++r)
    if (sendCounts[size_t(r)] > 0)
      copyRows(own.bytes().data(), &mine, sent.data() + sendOffsets[size_t(r)], nullptr,
               overlap(brick, regions[size_t(r)]), valueBytes);
  MPI_Alltoallv(sent.data(), sendCounts.data(), sendOffsets.data(), MPI_BYTE, received.data(),
                recvCounts.data(), recvOffsets.data(), MPI_BYTE, comm);
  if (brick.empty()) return Volume();

  const VoxelRegion& region = regions[size_t(rank)];
  const std::array<int64_t, 3> dims{region.hi[0] - region.lo[0], region.hi[1] - region.lo[1],
                                    region.hi[2] - region.lo[2]};
  std::vector<uint8_t> bytes(size_t(dims[0] * dims[1] * dims[2]) * valueBytes);
  copyRows(own.bytes().data(), &mine, bytes.data(), &region, overlap(brick, region), valueBytes);
  for (int r = 0; r < size; ++r)
    if (recvCounts[size_t(r)] > 0)
      copyRows(received.data() + recvOffsets[size_t(r)], nullptr, bytes.data(), &region,
               overlap(bricks[size_t(r)], region), valueBytes);
  const glm::dvec3 origin =
      own.worldPosition(double(region.lo[0] - brick.low[0]), double(region.lo[1] - brick.low[1]),
                        double(region.lo[2] - brick.low[2]));
  Volume out(dims, own.spacing(), origin, own.type(), std::move(bytes));
  out.setDirection(own.direction(), own.patientFrame());
  out.setUnit(own.unit());
  for (const std::string& note : own.notes()) out.addNote(note);
  for (const std::string& file : own.sourceFiles()) out.addSourceFile(file);
  return out;
}

}  // namespace ewa::dist
