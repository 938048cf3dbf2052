// Slices of a DICOM series at uneven places: which steps leave slices missing, the planes
// filled in, and uneven stacks resampled onto regular steps.
#include "io/dicom_gaps.h"

#include <gtest/gtest.h>

namespace ewa {
namespace {

using Runs = std::vector<int64_t>;

TEST(DicomGaps, StepsOfWholeMultiplesLeaveSlicesMissing) {
  EXPECT_EQ(missingSlicesAfter({2.0, 4.0, 2.0, 6.01}, 5), (Runs{0, 1, 0, 2}));
  // Within 1% of a multiple of the shortest step; else no gaps to fill.
  EXPECT_EQ(missingSlicesAfter({2.0, 2.0, 4.1}, 4), Runs{});
  EXPECT_EQ(missingSlicesAfter({2.0, 2.0, 5.0}, 4), Runs{});
  // Nothing missing.
  EXPECT_EQ(missingSlicesAfter({2.0, 2.01, 1.99}, 4), Runs{});
  // One short step among many: the series' step is not the shortest, nothing is filled.
  EXPECT_EQ(missingSlicesAfter({2.0, 2.0, 1.0, 2.0, 2.0}, 6), Runs{});
  // More missing than stored, or a run past the cap.
  EXPECT_EQ(missingSlicesAfter({1.0, 1.0, 5.0}, 3), Runs{});
  EXPECT_EQ(missingSlicesAfter({1.0, double(kMaxMissingRun + 2)}, 1000), Runs{});
  EXPECT_EQ(missingSlicesAfter({1.0, double(kMaxMissingRun + 1)}, 1000).back(), kMaxMissingRun);
  EXPECT_EQ(missingSlicesAfter({}, 1), Runs{});
  EXPECT_EQ(missingSlicesAfter({0.0, 1.0}, 3), Runs{});
}

TEST(DicomGaps, MissingPlanesAreLinearBetweenTheirNeighbours) {
  // Planes of two values: 0 and 10, then 30 and 40 with two missing between them.
  std::vector<double> values{0.0, 10.0, 30.0, 40.0, 60.0, 70.0};
  mixPlanes(values, 2, planesWithMissing({0, 2}), false);
  EXPECT_EQ(values,
            (std::vector<double>{0.0, 10.0, 30.0, 40.0, 40.0, 50.0, 50.0, 60.0, 60.0, 70.0}));
  std::vector<double> whole{0.0, 1.0};
  mixPlanes(whole, 1, planesWithMissing({2}), true);  // thirds of 1, rounded
  EXPECT_EQ(whole, (std::vector<double>{0.0, 0.0, 1.0, 1.0}));
}

// Planes at uneven places resampled onto regular steps about the median apart: each plane the
// value a linear function of the place has there, the first and last kept as they are.
TEST(DicomGaps, UnevenPlanesAreResampledOntoRegularSteps) {
  const std::vector<double> at{0.0, 2.0, 4.0, 9.0, 11.0};  // steps 2, 2, 5, 2: median 2
  const std::vector<PlaneMix> mix = regularPlanes(at);
  ASSERT_EQ(mix.size(), 7u);  // 11 / 2 rounds to 6 steps of 11/6
  std::vector<double> values;
  for (double z : at) values.push_back(3.0 * z + 1.0);  // one value a plane, linear in z
  mixPlanes(values, 1, mix, false);
  ASSERT_EQ(values.size(), 7u);
  for (size_t k = 0; k < 7; ++k) EXPECT_NEAR(values[k], 3.0 * (11.0 * k / 6.0) + 1.0, 1e-9) << k;
  // Each plane mixes the stored planes either side of its place.
  EXPECT_EQ(mix[3].below, 2u);  // 5.5 lies between 4 and 9
  EXPECT_NEAR(mix[3].weight, 0.3, 1e-12);
  // A stack mostly gap: at most twice the stored planes, still spanning first to last.
  const std::vector<PlaneMix> far = regularPlanes({0.0, 2.0, 4.0, 40.0});
  ASSERT_EQ(far.size(), 8u);
  EXPECT_EQ(far.back().below, 2u);
  EXPECT_DOUBLE_EQ(far.back().weight, 1.0);
  EXPECT_TRUE(regularPlanes({5.0}).empty());
  EXPECT_TRUE(regularPlanes({-1e308, 0.0, 1e308}).empty());  // overflows: not resampled
}

}  // namespace
}  // namespace ewa
