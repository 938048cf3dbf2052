// DistributedSession: the ranks' shared state across frames (source, split, this rank's brick and
// its ghosts, the agreed statistics and transfer function) and the collective frame.
#pragma once

#include <mpi.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "app/options.h"
#include "core/camera.h"
#include "core/splat_attributes.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "dist/brick_split.h"
#include "dist/mpi_brick_source.h"
#include "render/renderer.h"

namespace ewa::dist {

class BrickRenderer;
class IceTCompositor;

// One rank's figures of a frame (gathered on rank 0 by DistributedSession::render).
struct RankFigures {
  double renderMs = 0.0;     // its brick's frame, classification included
  double compositeMs = 0.0;  // its part of the composite (IceT or the reduction)
  double voxelsRead = 0.0;   // voxels held: brick and ghosts
  double peakRssMb = 0.0;    // the process's peak resident memory so far
  double bytesSent = 0.0;    // what it sent in the composite
  double splats = 0.0;       // its brick's splats (RenderStats::splatsTotal)
  double splatsDrawn = 0.0;  // of them, those in front of the eye
  double slabEntries = 0.0;  // splats drawn summed over slabs
  double slabs = 0.0;        // its frame's slabs
  double cpu = 0.0;          // 1 where its splats were drawn on the CPU
};

class DistributedSession {
 public:
  // Opens options' source on every rank of `comm`, splits the whole voxel box into one brick per
  // rank (k-d, by voxels), frames the camera on the whole volume and agrees on the value range,
  // histogram and transfer function (reading this rank's brick for them: the ghosts that the
  // initial camera's frame needs); with options.split "visible", splits again balanced by the
  // voxels visible under that transfer function and reads the bricks that moved. Collective.
  // Returns null on every rank after one rank printed one line ("ewaview-mpi: rank R of P: ...").
  static std::unique_ptr<DistributedSession> open(const Options& options, MPI_Comm comm);
  ~DistributedSession();
  DistributedSession(const DistributedSession&) = delete;
  DistributedSession& operator=(const DistributedSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm comm() const { return comm_; }
  const WholeGrid& grid() const { return source_->grid(); }
  const BrickSplit& split() const { return split_; }
  const std::string& name() const { return source_->name(); }
  // The camera framing the whole volume (initialCameraForBounds), the same on every rank.
  const Camera& initialCamera() const { return initialCamera_; }
  // The transfer function the ranks agreed on (options, sidecar, the volume's own or default).
  const TransferFunction& transferFunction() const { return transferFunction_; }
  // The ghost voxels each side of the brick of the last frame (of open's frame before any).
  const std::array<int64_t, 3>& ghost() const { return ghost_; }
  // This rank's brick volume: its voxels and ghosts, the whole's statistics and data box.
  const Volume& volume() const { return volume_; }
  // Where the bricks are read from (the window's rank reads its stand-in for the whole there).
  BrickSource& source() { return *source_; }

  // One frame of `width` x `height`: every rank draws its brick cut at its faces under the same
  // camera, settings and transfer function (the same arguments on every rank), the pictures are
  // blended in visibility order (composite), summed (X-ray) or maximal (MIP). A frame whose
  // kernels reach further than the ghosts held reads the brick again; a new transfer function
  // or classification classifies again. Collective. On rank 0 `whole` gets the picture
  // (readFramePicture's layout); on the others it is emptied. Returns false on every rank after
  // one rank printed one line.
  bool render(const Camera& camera, const RenderSettings& settings, const TransferFunction& tf,
              int width, int height, std::vector<float>* whole);
  // Rank 0: each rank's figures of the last frame; empty elsewhere.
  const std::vector<RankFigures>& figures() const { return figures_; }
  // Rank 0: the slowest rank's render and composite milliseconds of the last frame.
  double slowestRenderMs() const { return slowest(&RankFigures::renderMs); }
  double slowestCompositeMs() const { return slowest(&RankFigures::compositeMs); }
  // Rank 0: the renderer's note of the last frame on any rank ("" when none).
  const std::string& note() const { return note_; }

 private:
  DistributedSession(const Options& options, MPI_Comm comm);
  // The greatest of the ranks' `figure` in the last frame (rank 0).
  double slowest(double RankFigures::*figure) const;
  // Reads `region` into volume_ where `read`: collective where the source is scattered (rank 0
  // sends the regions of every rank that reads) or chunked (each rank reads its brick alone and
  // the ranks trade the ghost voxels). False on every rank after one line.
  bool readVoxels(bool read, const VoxelRegion& region);
  // Gives the brick volume just read the whole's statistics and data box.
  void finishBrick();
  // Splits again balanced by the voxels visible under the agreed transfer function and reads
  // the bricks that moved. Collective; false on every rank after one line.
  bool splitByVisibleVoxels(const Options& options);

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  std::string backend_, shaderDir_;
  std::unique_ptr<BrickSource> source_;
  BrickSplit split_;
  VoxelBox brick_;       // this rank's, in the whole volume's indices
  VoxelBox localBrick_;  // the same in volume_'s indices
  VoxelRegion region_;   // what volume_ holds
  std::array<int64_t, 3> ghost_{0, 0, 0};
  double lo_ = 0.0, hi_ = 0.0;  // the whole volume's value range
  std::vector<uint64_t> histogram_;
  Volume volume_;
  Camera initialCamera_;
  TransferFunction transferFunction_;
  long long voxelsRead_ = 0;
  // What the renderer's splats were classified under; volumeChanged_: they must be made again.
  bool volumeChanged_ = true;
  TransferFunction classifiedTf_;
  Classification classified_;
  std::unique_ptr<BrickRenderer> renderer_;
  std::unique_ptr<IceTCompositor> compositor_;
  std::vector<RankFigures> figures_;
  std::string note_;
};

}  // namespace ewa::dist
