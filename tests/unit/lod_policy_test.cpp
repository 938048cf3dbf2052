// Unit tests of the adaptive level-of-detail choice.
#include "core/lod_policy.h"

#include <gtest/gtest.h>

namespace ewa {
namespace {

TEST(LodPolicy, LevelsGetCheaperAndStartCoarse) {
  for (int l = 1; l < LodPolicy::kLevelCount; ++l)
    EXPECT_LT(LodPolicy::expectedCostRatio(l), LodPolicy::expectedCostRatio(l - 1));
  EXPECT_DOUBLE_EQ(LodPolicy::expectedCostRatio(0), 1.0);
  LodPolicy p(100.0, 150.0);
  EXPECT_EQ(p.movingLevel(), LodPolicy::kStartLevel);
  EXPECT_LT(p.measuredMs(1), 0.0);
}

TEST(LodPolicy, SlowFramesGoCoarserUntilTheLast) {
  LodPolicy p(100.0);
  int level = p.movingLevel();
  for (int n = 0; n < 10; ++n) {
    p.reportMovingFrame(level, 500.0);
    level = p.movingLevel();
  }
  EXPECT_EQ(level, LodPolicy::kLevelCount - 1);
}

TEST(LodPolicy, FastFramesGoFinerOnlyWhenTheFinerLevelShouldFit) {
  LodPolicy p(100.0);
  // Level 1 costs 0.5625 of full; at 10 ms full quality is expected at ~18 ms: go finer.
  p.reportMovingFrame(1, 10.0);
  EXPECT_EQ(p.movingLevel(), 0);
  // Full quality then measured over the target: back to level 1.
  p.reportMovingFrame(0, 180.0);
  EXPECT_EQ(p.movingLevel(), 1);
  // Level 1 fits but full quality is known to be too slow: stay, no oscillation.
  p.reportMovingFrame(1, 60.0);
  EXPECT_EQ(p.movingLevel(), 1);
  p.resetMeasurements();
  // 60 ms at level 1 predicts ~107 ms at full quality: over 80% of the target, stay.
  p.reportMovingFrame(1, 60.0);
  EXPECT_EQ(p.movingLevel(), 1);
}

TEST(LodPolicy, FirstMovingLevelFromTheFullQualityFrame) {
  LodPolicy p(100.0);
  p.startFromFullQuality(100.0);  // level 1 expected at 56 ms: fits
  EXPECT_EQ(p.movingLevel(), 1);
  EXPECT_EQ(p.measuredMs(0), 100.0);
  p.startFromFullQuality(1600.0);  // level 4 costs ~3.9% (62 ms), level 3 ~13% (206 ms)
  EXPECT_EQ(p.movingLevel(), 4);
  p.startFromFullQuality(1e6);  // nothing fits: the coarsest
  EXPECT_EQ(p.movingLevel(), LodPolicy::kLevelCount - 1);
}

TEST(LodPolicy, RefineAfterTheQuietDelay) {
  LodPolicy p(100.0, 150.0);
  EXPECT_FALSE(p.shouldRefine(149.0));
  EXPECT_TRUE(p.shouldRefine(150.0));
  p.reportMovingFrame(-1, 10.0);  // ignored
  p.reportMovingFrame(2, -5.0);   // ignored
  EXPECT_EQ(p.movingLevel(), LodPolicy::kStartLevel);
}

}  // namespace
}  // namespace ewa
