// Missing slices of a DICOM series: which steps are whole multiples, and the planes filled in.
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
  fillMissingSlices(values, 2, {0, 2}, false);
  EXPECT_EQ(values,
            (std::vector<double>{0.0, 10.0, 30.0, 40.0, 40.0, 50.0, 50.0, 60.0, 60.0, 70.0}));
  std::vector<double> whole{0.0, 1.0};
  fillMissingSlices(whole, 1, {2}, true);  // thirds of 1, rounded
  EXPECT_EQ(whole, (std::vector<double>{0.0, 0.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace ewa
