// ShearWarp: the CPU shear-warp volume renderer (standard or pre-integrated), without GL.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/image_metrics.h"
#include "core/intermediate_image.h"
#include "core/preintegration_table.h"
#include "core/shear_warp_compositor.h"
#include "core/shear_warp_factorization.h"
#include "core/shear_warp_settings.h"
#include "core/shear_warp_volume.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa {

struct ShearWarpStats {
  int principal = 2;
  int slices = 0;  // slices (standard) or slabs (pre-integrated) composited
  int intermediateWidth = 0, intermediateHeight = 0;
  double sampleRatio = 1.0;  // d'/d of this view
  double tableMs = 0.0;      // tables built or corrected for this frame
  double compositeMs = 0.0;
  double warpMs = 0.0;
  double visibleCells = 1.0;  // fraction of cells the transfer function leaves visible
  bool perspectiveAsParallel = false;
};

class ShearWarp {
 public:
  // The volume must outlive this object or the next setVolume call.
  void setVolume(const Volume& volume);
  void setTransferFunction(const TransferFunction& tf);
  // Renders a width x height picture: premultiplied RGBA, top row first (see image()).
  // Samples outside `clip` (crop box and clipping planes, world space) are skipped.
  void render(const Camera& camera, const ShearWarpSettings& settings, int width, int height,
              const ClipRegion& clip = {});

  const FloatImage& image() const { return image_; }
  // Builds now what render() otherwise builds on first use: the slice copies and run-length
  // encodings of every principal axis (for benchmarks, so no variant pays for them).
  void prepareAllAxes(int tableSize = 256);

  const IntermediateImage& intermediate() const { return intermediate_; }
  const ShearWarpStats& stats() const { return stats_; }
  // The pre-integration table for segments of length `distance` under the current transfer
  // function and table size (built if needed). Milliseconds of the last build: lastBuildMs().
  const PreintegrationTable& pairTable(double distance, int size);
  double lastBuildMs() const { return lastBuildMs_; }

 private:
  void prepare(int tableSize);
  const std::vector<glm::vec4>& correctedTable(const ShearWarpFactorization& view,
                                               const ShearWarpSettings& settings);
  // ln(1 - alpha) of each entry of the last corrected table (made on first use after it).
  const std::vector<float>& correctedLog();

  const Volume* volume_ = nullptr;
  TransferFunction tf_;
  bool volumeDirty_ = true, tfDirty_ = true;
  int tableSize_ = 0;
  ShearWarpVolume data_;
  std::map<double, PreintegrationTable> pairTables_;      // by segment length
  std::map<double, std::vector<glm::vec4>> pointTables_;  // by sample distance
  // The last corrected table and what it was made for.
  std::vector<glm::vec4> corrected_;
  std::vector<float> correctedLog_;  // ln(1 - alpha) of each entry of corrected_
  bool correctedValid_ = false;
  bool correctedPre_ = false;
  double correctedDistance_ = 0.0, correctedRatio_ = 0.0;
  CompositorBuffers buffers_;
  IntermediateImage intermediate_;
  FloatImage image_;
  ShearWarpStats stats_;
  double lastBuildMs_ = 0.0;
};

// Threads the settings ask for: settings.threads, or every hardware thread when 0.
int shearWarpThreads(const ShearWarpSettings& settings);

}  // namespace ewa
