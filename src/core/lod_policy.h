// LodPolicy: which level of detail to draw while the view moves, chosen from measured frame
// times, and when to refine to full quality (pure logic, no GL).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace ewa {

// A level of detail: the volume downsampled by volumeFactor per axis, drawn into an image
// 1/imageDivisor the window's size (then scaled up). {1, 1} is full quality.
struct LodLevel {
  int volumeFactor = 1;
  int imageDivisor = 1;
};

class LodPolicy {
 public:
  // Level 0 is full quality; each next level is cheaper. The volume factors (2, 4, 8, 16) are
  // the downsampled volumes the viewer keeps (16 only for big volumes: keepsVolumeFactor).
  // {8, 4} and {8, 8} are for big volumes and fill-bound views on slow GL (llvmpipe): a
  // close-up of CThead still overruns a UI frame at {8, 4}. {16, 8} is for splat-bound views of
  // volumes of 512^3 and so: a dense one's volume/8 (262 k splats) overruns one at {8, 8}.
  static constexpr std::array<LodLevel, 8> kLevels{
      {{1, 1}, {2, 1}, {2, 2}, {4, 2}, {4, 4}, {8, 4}, {8, 8}, {16, 8}}};
  static constexpr int kLevelCount = int(kLevels.size());
  // A volume factor over 8 is kept only where volume/8 still holds more than this many voxels
  // (volumes of about 320^3 and up): below that, volume/8 has few enough slab entries for
  // llvmpipe's vertex stage, so volume/8 of a dense 256^3 volume (32 k voxels) fits a moving frame,
  // and a volume/16 of it (16^3) would only blur a picture nothing needed to be faster.
  static constexpr long long kMaxCoarseVoxels = 65536;
  static bool keepsVolumeFactor(int factor, long long voxels);
  // The coarsest level whose volume factor is kept for a volume of `voxels` voxels.
  static int coarsestLevelFor(long long voxels);
  // Start at volume/2 and image/2: safe for both splat-bound (big volumes) and fill-bound
  // (magnified small volumes) cases; measurements move it from there.
  static constexpr int kStartLevel = 2;
  // A finer level not measured yet is expected to render at least this many times as long as
  // the level just measured: each step halves the volume or the image per axis, and on llvmpipe
  // a step at the coarse levels costs about this much (the default volume and engine in the
  // window), where the mean in expectedCostRatio says 1.2x for volume/8 to volume/4 at image/4
  // (twice the slabs over the same pixels): a guess that low overruns the 100 ms bound at every
  // transfer-function drag.
  static constexpr double kMinStepRatio = 2.5;
  // From volume/16 to volume/8 at once: volume/16 is kept only for volumes splat-bound at
  // volume/8, which has 8 times the splats: on llvmpipe a dense 512^3 volume's volume/8 frame
  // costs several times its volume/16 one, and a guess of 2.5x lets every orbit overrun the bound.
  static constexpr double kMinStepRatioFromSixteen = 4.0;
  // The least ratio expected between `level` and the coarser level `coarser` (the product of
  // the steps' least ratios).
  static double minStepRatio(int level, int coarser);

  // targetMs: the frame time to stay under while moving; refineDelayMs: quiet time after the
  // last input before the full-quality frame.
  explicit LodPolicy(double targetMs = 100.0, double refineDelayMs = 150.0);

  // The level to draw the next moving frame with.
  int movingLevel() const { return level_; }
  static const LodLevel& level(int index) { return kLevels[std::size_t(index)]; }
  // Records how long a moving frame at `level` took, `renderMs` drawing the level and
  // `overheadMs` the rest of the UI frame (panels, present, swap: the same at every level), and
  // picks the next moving level: coarser when the whole frame is over the target, finer when
  // the finer level is known (or expected: the overhead plus the render times its cost ratio,
  // at least minStepRatio) to fit under 80% of the target.
  void reportMovingFrame(int level, double renderMs, double overheadMs = 0.0);
  // Picks the first moving level from a measured full-quality frame: the finest coarse level
  // expected (by expectedCostRatio) to fit under 80% of the target, else the coarsest. Moving
  // frames measured later take over.
  void startFromFullQuality(double fullMs);
  // True once `msSinceInput` of quiet has passed: draw full quality.
  bool shouldRefine(double msSinceInput) const { return msSinceInput >= refineDelayMs_; }
  double targetMs() const { return targetMs_; }
  double refineDelayMs() const { return refineDelayMs_; }
  // Last measured time per level (negative: not measured yet).
  double measuredMs(int level) const { return measured_[std::size_t(level)]; }
  // Forgets the measurements (a new volume or transfer function changes the costs).
  void resetMeasurements();
  // The coarsest level this volume has (coarsestLevelFor; every level until set): the moving
  // level goes no coarser.
  void setCoarsestLevel(int level);
  // The window now has `pixelRatio` times the pixels the measurements were made at. Larger:
  // each measured frame is expected to cost that many times as much (the coarse levels' large
  // footprints are fill-bound on llvmpipe, and the present and swap grow with the window too, so
  // a level picked in a small window overruns the target in a much larger one), and
  // the moving level goes coarser until its expected frame fits under 80% of the target.
  // Smaller: the measurements shrink the same way (a window made large and small again finds
  // its levels as they were), the level stays, and moving frames take it finer as their
  // expected costs allow (one that is over the target goes back at once).
  void resized(double pixelRatio);

  // Expected cost of `level` relative to full quality: splats scale with 1/factor^3, pixels
  // with 1/divisor^2; the slower of the two dominates, so take their mean as a rough guess.
  static double expectedCostRatio(int level);

 private:
  double targetMs_;
  double refineDelayMs_;
  int level_ = kStartLevel;
  int coarsest_ = kLevelCount - 1;
  std::array<double, kLevelCount> measured_{};
};

}  // namespace ewa
