// StepCostModel: prices of entries, pass pixels and opacity checks learnt from chunk times.
#include "core/step_cost_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ewa {
namespace {

StepCostModel::Chunk chunk(double ms, size_t entries, long long pixels, size_t checks,
                           size_t begins = 0) {
  return {ms, entries, pixels, checks, begins};
}

// Chunks priced by a true model: 0.003 ms an entry, 1e-4 ms a pass pixel (40 ms a slab of
// 400,000 pixels), 15 ms a check.
double trueMs(size_t entries, long long pixels, size_t checks) {
  return 0.003 * double(entries) + 1e-4 * double(pixels) + 15.0 * double(checks);
}

TEST(StepCostModel, LearnsEachPriceFromTheChunksThatShowIt) {
  StepCostModel m;
  EXPECT_FALSE(m.measured());
  m.update(chunk(trueMs(10000, 0, 0), 10000, 0, 0));  // entries alone
  ASSERT_TRUE(m.measured());
  EXPECT_NEAR(m.msPerEntry(), 0.003, 1e-12);
  EXPECT_EQ(m.finishMs(400000, false), 0.0);
  m.update(chunk(trueMs(2000, 400000, 0), 2000, 400000, 0));  // a plain pass: the rest is its price
  EXPECT_NEAR(m.msPerPixel(), 1e-4, 1e-12);
  EXPECT_NEAR(m.finishMs(400000, false), 40.0, 1e-9);
  m.update(chunk(trueMs(0, 100000, 1), 0, 100000, 1));  // with a check: the excess is the check's
  EXPECT_NEAR(m.finishMs(400000, false), 40.0, 1e-9);
  EXPECT_NEAR(m.finishMs(400000, true), 55.0, 1e-9);
  EXPECT_NEAR(m.checkMs(), 15.0, 1e-9);
  EXPECT_NEAR(m.slabMs(1000, 400000, true), 58.0, 1e-9);
  // A band of a pass alone, and a check alone (a slab whose rectangle is empty).
  m.update(chunk(trueMs(0, 50000, 0), 0, 50000, 0));
  EXPECT_NEAR(m.msPerPixel(), 1e-4, 1e-12);
  m.update(chunk(trueMs(0, 0, 1), 0, 0, 1));
  EXPECT_NEAR(m.checkMs(), 15.0, 1e-9);
  // Mixed chunks: entries, three slabs' pixels, one check.
  m.update(chunk(trueMs(500, 1200000, 1), 500, 1200000, 1));
  EXPECT_NEAR(m.finishMs(400000, true), 55.0, 1e-9);
}

TEST(StepCostModel, GoesUpAtOnceAndDownByHalves) {
  StepCostModel m;
  m.update(chunk(30.0, 10000, 0, 0));  // 0.003
  m.update(chunk(60.0, 10000, 0, 0));  // dearer: taken at once
  EXPECT_NEAR(m.msPerEntry(), 0.006, 1e-12);
  m.update(chunk(20.0, 10000, 0, 0));  // cheaper: half way down
  EXPECT_NEAR(m.msPerEntry(), 0.004, 1e-12);
  m.update(chunk(40.0 + 30.0, 10000, 100000, 0));
  EXPECT_NEAR(m.finishMs(100000, false), 30.0, 1e-9);  // 70 - 0.004 * 10000
  m.update(chunk(10.0, 0, 100000, 0));
  EXPECT_NEAR(m.finishMs(100000, false), 20.0, 1e-9);
}

TEST(StepCostModel, ChargesUnknownPricesHigh) {
  // A pass before any entry price is known: all charged to the entries.
  StepCostModel m;
  m.update(chunk(50.0, 1000, 100000, 0));
  EXPECT_NEAR(m.msPerEntry(), 0.05, 1e-12);
  EXPECT_EQ(m.finishMs(100000, false), 0.0);
  // A checked pass before a pixel's price is known: all charged to the pixels.
  StepCostModel c;
  c.update(chunk(trueMs(1000, 0, 0), 1000, 0, 0));
  c.update(chunk(trueMs(1000, 400000, 1), 1000, 400000, 1));
  EXPECT_NEAR(c.finishMs(400000, false), 55.0, 1e-9);
  EXPECT_NEAR(c.finishMs(400000, true), 55.0, 1e-9);
  // A chunk faster than its entries' price gives pixels of no cost, never negative ones.
  c.update(chunk(1.0, 1000, 400000, 0));
  EXPECT_GE(c.finishMs(400000, false), 0.0);
  EXPECT_NEAR(c.finishMs(400000, false), 27.5, 1e-9);
}

TEST(StepCostModel, IgnoresTimesThatAreNotTimesAndEmptyChunks) {
  StepCostModel m;
  m.update(chunk(std::numeric_limits<double>::quiet_NaN(), 100, 0, 0));
  m.update(chunk(std::numeric_limits<double>::infinity(), 100, 0, 0));
  m.update(chunk(-1.0, 100, 0, 0));
  m.update(chunk(5.0, 0, 0, 0));  // nothing drawn: nothing to price
  EXPECT_FALSE(m.measured());
  m.update(chunk(1.0, 100, 0, 0));
  m.update(chunk(std::numeric_limits<double>::quiet_NaN(), 100, 1000, 1));
  m.update(chunk(3.0, 0, 0, 0));
  EXPECT_NEAR(m.msPerEntry(), 0.01, 1e-12);
  EXPECT_EQ(m.finishMs(1000, true), 0.0);
  m.update(chunk(1.0 + 2.0, 100, -5, 0));  // negative pixels count as none: the entries' time
  EXPECT_NEAR(m.msPerEntry(), 0.03, 1e-12);
}

// Slabs begun (their clears) priced apart: learnt from the chunk that first shows one, then
// scaled with the other known prices of the chunks that hold them.
TEST(StepCostModel, LearnsTheClearsOfSlabsBegun) {
  StepCostModel m;
  m.update(chunk(30.0, 10000, 0, 0));            // 0.003 an entry
  m.update(chunk(30.0 + 12.0, 10000, 0, 0, 1));  // a slab begun: 12 ms of clears
  EXPECT_NEAR(m.beginMs(), 12.0, 1e-9);
  EXPECT_NEAR(m.slabMs(1000, 0, false), 15.0, 1e-9);
  m.update(chunk(30.0 + 12.0 + 40.0, 10000, 400000, 0, 1));  // pixels unknown: the rest
  EXPECT_NEAR(m.msPerPixel(), 1e-4, 1e-12);
  // Twice what the known prices of a chunk predict: both doubled at once.
  m.update(chunk(30.0 + 2.0 * (12.0 + 40.0), 10000, 400000, 0, 1));
  EXPECT_NEAR(m.beginMs(), 24.0, 1e-9);
  EXPECT_NEAR(m.msPerPixel(), 2e-4, 1e-12);
  // Half of it: half way down.
  m.update(chunk(30.0 + 0.5 * (24.0 + 80.0), 10000, 400000, 0, 1));
  EXPECT_NEAR(m.beginMs(), 18.0, 1e-9);
  EXPECT_NEAR(m.msPerPixel(), 1.5e-4, 1e-12);
}

// A step's rows of a slab's pass: 0.1 ms a row, bands of 16 rows, at least 32.
TEST(PassRowsToDraw, WholeBandsThatFitAndAtLeastOneAsAStepsFirstWork) {
  EXPECT_EQ(passRowsToDraw(200, 0.1, 20.0, false, 16, 32), 200);  // all fit
  EXPECT_EQ(passRowsToDraw(200, 0.1, 10.0, false, 16, 32), 96);   // 100 fit: whole bands
  EXPECT_EQ(passRowsToDraw(200, 0.1, 10.0, true, 16, 32), 96);
  EXPECT_EQ(passRowsToDraw(200, 0.1, 2.0, false, 16, 32), 0);     // 20 fit: none after other work
  EXPECT_EQ(passRowsToDraw(200, 0.1, 2.0, true, 16, 32), 32);     // a step's first work: one band
  EXPECT_EQ(passRowsToDraw(200, 0.1, -5.0, true, 16, 32), 32);    // even over budget already
  EXPECT_EQ(passRowsToDraw(200, 0.1, 18.0, false, 16, 32), 200);  // 176 would leave a sliver
  EXPECT_EQ(passRowsToDraw(50, 0.1, 0.0, true, 16, 32), 50);      // likewise
  EXPECT_EQ(passRowsToDraw(0, 0.1, -1.0, false, 16, 32), 0);      // nothing left
  EXPECT_EQ(passRowsToDraw(200, 0.0, 1.0, false, 16, 32), 200);   // rows of no width
}

}  // namespace
}  // namespace ewa
