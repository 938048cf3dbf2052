// LodPolicy: adaptive choice of the level of detail from measured frame times.
#include "core/lod_policy.h"

#include <algorithm>
#include <cmath>

namespace ewa {

LodPolicy::LodPolicy(double targetMs, double refineDelayMs)
    : targetMs_(targetMs), refineDelayMs_(refineDelayMs) {
  resetMeasurements();
}

void LodPolicy::resetMeasurements() {
  measured_.fill(-1.0);
  level_ = std::min(kStartLevel, coarsest_);
}

bool LodPolicy::keepsVolumeFactor(int factor, long long voxels) {
  if (factor <= 8) return true;
  const long long half = factor / 2;  // the next finer factor's volume
  return voxels / (half * half * half) > kMaxCoarseVoxels;
}

int LodPolicy::coarsestLevelFor(long long voxels) {
  int coarsest = 0;
  for (int l = 1; l < kLevelCount; ++l)
    if (keepsVolumeFactor(kLevels[size_t(l)].volumeFactor, voxels)) coarsest = l;
  return coarsest;
}

double LodPolicy::minStepRatio(int level, int coarser) {
  double ratio = 1.0;
  for (int l = level; l < coarser; ++l)
    ratio *= kLevels[size_t(l + 1)].volumeFactor > 8 ? kMinStepRatioFromSixteen : kMinStepRatio;
  return ratio;
}

void LodPolicy::setCoarsestLevel(int level) {
  coarsest_ = std::clamp(level, 1, kLevelCount - 1);
  level_ = std::min(level_, coarsest_);
}

double LodPolicy::expectedCostRatio(int index) {
  const LodLevel& l = kLevels[size_t(index)];
  const double f = l.volumeFactor, d = l.imageDivisor;
  return 0.5 * (1.0 / (f * f * f) + 1.0 / (d * d));
}

void LodPolicy::startFromFullQuality(double fullMs) {
  if (!(fullMs >= 0.0)) return;
  measured_[0] = fullMs;
  level_ = coarsest_;
  for (int l = 1; l < coarsest_; ++l) {
    if (fullMs * expectedCostRatio(l) < 0.8 * targetMs_) {
      level_ = l;
      return;
    }
  }
}

void LodPolicy::resized(double pixelRatio) {
  if (!(pixelRatio > 0.0) || !std::isfinite(pixelRatio)) return;
  for (double& ms : measured_)
    if (ms >= 0.0) ms *= pixelRatio;
  if (pixelRatio < 1.0) return;  // moving frames go finer as the smaller costs allow
  // The moving level's expected frame: its measurement, else the nearest coarser one's times
  // the cost ratio as reportMovingFrame guesses it, else the nearest finer one's times the cost
  // ratio as startFromFullQuality does.
  auto expected = [this](int level) {
    for (int l = level; l <= coarsest_; ++l)
      if (measured_[size_t(l)] >= 0.0)
        return measured_[size_t(l)] *
               std::max(minStepRatio(level, l), expectedCostRatio(level) / expectedCostRatio(l));
    for (int l = level - 1; l >= 0; --l)
      if (measured_[size_t(l)] >= 0.0)
        return measured_[size_t(l)] * expectedCostRatio(level) / expectedCostRatio(l);
    return 0.0;  // nothing measured: no reason to move
  };
  while (level_ < coarsest_ && expected(level_) >= 0.8 * targetMs_) ++level_;
}

void LodPolicy::reportMovingFrame(int index, double renderMs, double overheadMs) {
  if (index < 0 || index > coarsest_ || !(renderMs >= 0.0)) return;
  if (!(overheadMs >= 0.0)) overheadMs = 0.0;
  const double ms = renderMs + overheadMs;
  measured_[size_t(index)] = ms;
  level_ = index;
  if (ms > targetMs_) {
    level_ = std::min(index + 1, coarsest_);
    return;
  }
  if (index == 0) return;
  const int finer = index - 1;
  double expected = measured_[size_t(finer)];
  if (expected < 0.0)
    expected =
        overheadMs + renderMs * std::max(minStepRatio(finer, index),
                                         expectedCostRatio(finer) / expectedCostRatio(index));
  if (expected < 0.8 * targetMs_) level_ = finer;
}

}  // namespace ewa
