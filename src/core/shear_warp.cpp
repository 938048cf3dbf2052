// ShearWarp: ties factorization, tables, run-length encoding, compositing and warp together.
#include "core/shear_warp.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "core/named_values.h"
#include "core/opacity_correction.h"
#include "core/stopwatch.h"
#include "core/volume_orientation.h"

namespace ewa {

namespace {

using Clock = std::chrono::steady_clock;

constexpr NamedValue<TableLookup> kTableLookupNames[] = {{TableLookup::Nearest, "nearest"},
                                                         {TableLookup::Bilinear, "bilinear"}};
}  // namespace

const char* tableLookupName(TableLookup lookup) {
  return nameIn(kTableLookupNames, lookup);
}

bool parseTableLookup(const std::string& text, TableLookup* lookup) {
  return parseIn(kTableLookupNames, text, lookup);
}

std::vector<std::string> tableLookupNames() {
  return namesIn(kTableLookupNames);
}

namespace {
constexpr NamedValue<BufferSlices> kBufferSlicesNames[] = {{BufferSlices::Slice, "slice"},
                                                           {BufferSlices::Image, "image"}};
}  // namespace

const char* bufferSlicesName(BufferSlices buffers) {
  return nameIn(kBufferSlicesNames, buffers);
}

bool parseBufferSlices(const std::string& text, BufferSlices* buffers) {
  return parseIn(kBufferSlicesNames, text, buffers);
}

std::vector<std::string> bufferSlicesNames() {
  return namesIn(kBufferSlicesNames);
}

int shearWarpThreads(const ShearWarpSettings& settings) {
  if (settings.threads > 0) return settings.threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

void ShearWarp::setVolume(const Volume& volume) {
  volume_ = &volume;
  volumeDirty_ = true;
}

void ShearWarp::setTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  tfDirty_ = true;
}

void ShearWarp::prepare(int tableSize) {
  if (!volume_) return;
  if (tableSize != tableSize_) {
    tableSize_ = tableSize;
    volumeDirty_ = true;
  }
  const double lo = volume_->minValue(), hi = volume_->maxValue();
  if (volumeDirty_) {
    data_.setVolume(*volume_, lo, hi, tableSize_);
    tfDirty_ = true;
    volumeDirty_ = false;
  }
  if (!tfDirty_) return;
  tfDirty_ = false;
  pairTables_.clear();
  pointTables_.clear();
  correctedValid_ = false;
  // A table interval is visible when the function has alpha > 0 anywhere in it.
  std::vector<uint8_t> visible(tableSize_ - 1);
  const double width = hi > lo ? (hi - lo) / (tableSize_ - 1) : 0.0;
  for (int m = 0; m + 1 < tableSize_; ++m)
    visible[m] = !tf_.allTransparent(lo + m * width, lo + (m + 1) * width);
  data_.setVisibility(visible);
}

void ShearWarp::prepareAllAxes(int tableSize) {
  prepare(tableSize);
  for (int axis = 0; axis < 3; ++axis) {
    data_.slices(axis);
    data_.runs(axis, false);
    data_.runs(axis, true);
  }
}

const PreintegrationTable& ShearWarp::pairTable(double distance, int size) {
  prepare(size);
  auto it = pairTables_.find(distance);
  if (it == pairTables_.end()) {
    const auto start = Clock::now();
    const double lo = volume_ ? volume_->minValue() : 0.0, hi = volume_ ? volume_->maxValue() : 1.0;
    it = pairTables_.emplace(distance, PreintegrationTable::build(tf_, lo, hi, size, distance))
             .first;
    lastBuildMs_ = millisecondsSince(start);
  }
  return it->second;
}

const std::vector<glm::vec4>& ShearWarp::correctedTable(const ShearWarpFactorization& view,
                                                        const ShearWarpSettings& s) {
  const double d = view.sliceSpacing;
  // Perspective views correct each ray for its own ratio as they composite (rayRatio).
  const double ratio = s.opacityCorrection && !view.perspective ? view.sampleRatio : 1.0;
  if (correctedValid_ && correctedPre_ == s.preintegrated && correctedDistance_ == d &&
      correctedRatio_ == ratio)
    return corrected_;
  if (s.preintegrated) {
    // Diagonal-major copy: entry (f, b) at (b - f + n - 1) * n + f. Adjacent slices hold
    // similar values, so lookups stay near the diagonal, which this layout keeps in a few
    // contiguous rows (cache lines) instead of one row of the table per front value.
    const std::vector<glm::vec4>& table = pairTable(d, tableSize_).entries();
    const int n = tableSize_;
    corrected_.assign(size_t(2 * n - 1) * n, glm::vec4(0.0f));
    for (int f = 0; f < n; ++f)
      for (int b = 0; b < n; ++b)
        corrected_[size_t(b - f + n - 1) * n + f] = table[size_t(f) * n + b];
  } else {
    auto it = pointTables_.find(d);
    if (it == pointTables_.end())
      it = pointTables_
               .emplace(
                   d, buildPointTable(tf_, volume_->minValue(), volume_->maxValue(), tableSize_, d))
               .first;
    corrected_ = it->second;
  }
  // Lacroute corrects through a table of alpha; correcting the classification table once per
  // view gives the same numbers for every sample at the cost of one pass over the table.
  correctTable(corrected_, ratio);
  correctedLog_.clear();  // made again when a perspective view asks (correctedLog)
  correctedValid_ = true;
  correctedPre_ = s.preintegrated;
  correctedDistance_ = d;
  correctedRatio_ = ratio;
  return corrected_;
}

const std::vector<float>& ShearWarp::correctedLog() {
  // ln(1 - alpha) of each entry: perspective views correct each ray's samples with one exp.
  // Parallel views, whose table the view's ratio corrects (every frame while turning), never
  // read it; a perspective view's table is corrected for 1, so this is made once a table.
  if (correctedLog_.size() != corrected_.size()) {
    correctedLog_.resize(corrected_.size());
    for (size_t e = 0; e < corrected_.size(); ++e)
      correctedLog_[e] = corrected_[e].a < 1.0f ? std::log1p(-corrected_[e].a) : -INFINITY;
  }
  return correctedLog_;
}

void ShearWarp::render(const Camera& camera, const ShearWarpSettings& settings, int width,
                       int height, const ClipRegion& clip) {
  stats_ = ShearWarpStats{};
  image_ = FloatImage(std::max(1, width), std::max(1, height), 4, 0.0f);
  if (!volume_ || volume_->empty() || !camera.valid()) return;
  const int size = std::clamp(settings.tableSize, 2, 256);
  prepare(size);
  // Shear-warp works in voxel space: the volume's own frame under the rigidly moved camera.
  const ShearWarpFactorization view =
      factorizeView(cameraInVolumeFrame(camera, *volume_), volume_->dims(), volume_->spacing(),
                    volume_->origin(), width, height, settings.intermediateScale);
  stats_.principal = view.principal;
  stats_.sampleRatio = view.sampleRatio;
  stats_.perspectiveAsParallel = view.perspectiveAsParallel;
  stats_.visibleCells = data_.visibleFraction();
  stats_.intermediateWidth = view.imageWidth;
  stats_.intermediateHeight = view.imageHeight;
  stats_.slices = settings.preintegrated ? std::max(0, view.sliceCount - 1) : view.sliceCount;

  auto start = Clock::now();
  CompositeInput input;
  input.view = &view;
  input.settings = settings;
  input.tableSize = size;
  const ShearWarpClip clipCells(clip, *volume_, view);
  input.clip = &clipCells;
  const std::vector<glm::vec4>& table = correctedTable(view, settings);
  (settings.preintegrated ? input.pairTable : input.pointTable) = table.data();
  if (view.perspective && settings.opacityCorrection) input.tableLog = correctedLog().data();
  input.slices = data_.slices(view.principal).data();
  input.runs = &data_.runs(view.principal, settings.preintegrated);
  // Without run-length encoding every cell is one run (for tests: the picture must not change).
  CellRuns everything;
  if (!settings.runLengthEncoding) {
    everything.rows = std::max(0, view.height - 1);
    const int cells = std::max(0, view.width - 1);
    everything.offsets.resize(size_t(view.depth) * everything.rows + 1);
    for (size_t r = 0; r + 1 < everything.offsets.size(); ++r) {
      everything.runs.push_back({0, cells});
      everything.offsets[r + 1] = int32_t(r + 1);
    }
    input.runs = &everything;
  }
  stats_.tableMs = millisecondsSince(start);

  start = Clock::now();
  const int threads = shearWarpThreads(settings);
  compositeSlices(input, threads, buffers_, intermediate_);
  stats_.compositeMs = millisecondsSince(start);

  start = Clock::now();
  image_ = warpImage(intermediate_, view.inverseWarp, width, height, threads);
  stats_.warpMs = millisecondsSince(start);
}

}  // namespace ewa
