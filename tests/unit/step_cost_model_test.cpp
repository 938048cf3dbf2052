// StepCostModel: prices of entries, slab finishes and opacity checks learnt from chunk times.
#include "core/step_cost_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ewa {
namespace {

// Chunks priced by a true model: 0.003 ms an entry, 40 ms a finish, 15 ms more with a check.
double trueMs(size_t entries, size_t finishes, size_t checks) {
  return 0.003 * double(entries) + 40.0 * double(finishes) + 15.0 * double(checks);
}

TEST(StepCostModel, LearnsEachPriceFromTheChunksThatShowIt) {
  StepCostModel m;
  EXPECT_FALSE(m.measured());
  m.update(trueMs(10000, 0, 0), 10000, 0, 0);  // entries alone
  ASSERT_TRUE(m.measured());
  EXPECT_NEAR(m.msPerEntry(), 0.003, 1e-12);
  EXPECT_EQ(m.finishMs(false), 0.0);
  m.update(trueMs(2000, 1, 0), 2000, 1, 0);  // a plain finish: the rest is its price
  EXPECT_NEAR(m.finishMs(false), 40.0, 1e-9);
  m.update(trueMs(0, 1, 1), 0, 1, 1);  // a finish with the check: the excess is the check's
  EXPECT_NEAR(m.finishMs(false), 40.0, 1e-9);
  EXPECT_NEAR(m.finishMs(true), 55.0, 1e-9);
  EXPECT_NEAR(m.slabMs(1000, true), 58.0, 1e-9);
  // Mixed chunks: three finishes, one checked.
  m.update(trueMs(500, 3, 1), 500, 3, 1);
  EXPECT_NEAR(m.finishMs(true), 55.0, 1e-9);
}

TEST(StepCostModel, GoesUpAtOnceAndDownByHalves) {
  StepCostModel m;
  m.update(30.0, 10000, 0, 0);  // 0.003
  m.update(60.0, 10000, 0, 0);  // dearer: taken at once
  EXPECT_NEAR(m.msPerEntry(), 0.006, 1e-12);
  m.update(20.0, 10000, 0, 0);  // cheaper: half way down
  EXPECT_NEAR(m.msPerEntry(), 0.004, 1e-12);
  m.update(30.0 + 40.0, 10000, 1, 0);
  EXPECT_NEAR(m.finishMs(false), 30.0, 1e-9);  // 70 - 0.004 * 10000
  m.update(10.0, 0, 1, 0);
  EXPECT_NEAR(m.finishMs(false), 20.0, 1e-9);
}

TEST(StepCostModel, ChargesUnknownPricesHigh) {
  // A finish before any entry price is known: all charged to the entries.
  StepCostModel m;
  m.update(50.0, 1000, 1, 0);
  EXPECT_NEAR(m.msPerEntry(), 0.05, 1e-12);
  EXPECT_EQ(m.finishMs(false), 0.0);
  // A checked finish before a plain one is known: all charged to the finish.
  StepCostModel c;
  c.update(trueMs(1000, 0, 0), 1000, 0, 0);
  c.update(trueMs(1000, 1, 1), 1000, 1, 1);
  EXPECT_NEAR(c.finishMs(false), 55.0, 1e-9);
  EXPECT_NEAR(c.finishMs(true), 55.0, 1e-9);
  // A chunk faster than its entries' price gives finishes of no cost, never negative ones.
  c.update(1.0, 1000, 1, 0);
  EXPECT_GE(c.finishMs(false), 0.0);
  EXPECT_NEAR(c.finishMs(false), 27.5, 1e-9);
}

TEST(StepCostModel, IgnoresTimesThatAreNotTimes) {
  StepCostModel m;
  m.update(std::numeric_limits<double>::quiet_NaN(), 100, 0, 0);
  m.update(std::numeric_limits<double>::infinity(), 100, 0, 0);
  m.update(-1.0, 100, 0, 0);
  EXPECT_FALSE(m.measured());
  m.update(1.0, 100, 0, 0);
  m.update(std::numeric_limits<double>::quiet_NaN(), 100, 1, 1);
  EXPECT_NEAR(m.msPerEntry(), 0.01, 1e-12);
  EXPECT_EQ(m.finishMs(true), 0.0);
  // More checks than finishes cannot be: counted as one a finish.
  m.update(1.0 + 30.0, 100, 1, 0);
  m.update(1.0 + 50.0, 100, 1, 5);
  EXPECT_NEAR(m.finishMs(true), 50.0, 1e-9);
}

}  // namespace
}  // namespace ewa
