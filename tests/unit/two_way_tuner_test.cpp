// TwoWayTuner: both ways tried first, then the cheaper kept, the other retried every kRetryEvery.
#include "core/two_way_tuner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ewa {
namespace {

// Runs `frames` frames whose way w costs costs[w], returning the ways taken.
std::vector<int> run(TwoWayTuner& t, int frames, double cost0, double cost1) {
  std::vector<int> ways;
  for (int i = 0; i < frames; ++i) {
    const int way = t.choice();
    ways.push_back(way);
    t.report(way, way == 0 ? cost0 : cost1);
  }
  return ways;
}

TEST(TwoWayTuner, TriesBothThenKeepsTheCheaperAndRetriesTheOther) {
  TwoWayTuner t;
  const std::vector<int> ways = run(t, 2 + 2 * (TwoWayTuner::kRetryEvery + 1), 2.0, 1.0);
  EXPECT_EQ(ways[0], 0);
  EXPECT_EQ(ways[1], 1);
  int zeros = 0;
  for (size_t i = 2; i < ways.size(); ++i) {
    zeros += ways[i] == 0;
    // The retries: the frame after every kRetryEvery frames of the cheaper way.
    const bool retry = (i - 2) % (TwoWayTuner::kRetryEvery + 1) == size_t(TwoWayTuner::kRetryEvery);
    EXPECT_EQ(ways[i], retry ? 0 : 1) << i;
  }
  EXPECT_EQ(zeros, 2);
  EXPECT_DOUBLE_EQ(t.cost(0), 2.0);
  EXPECT_DOUBLE_EQ(t.cost(1), 1.0);
}

TEST(TwoWayTuner, FollowsACostThatChanges) {
  TwoWayTuner t;
  run(t, 10, 1.0, 3.0);  // way 0 cheaper
  EXPECT_EQ(t.choice(), 0);
  // Way 0 turns dear (another view): seen in its next frame, so the next takes way 1.
  t.report(0, 5.0);
  EXPECT_EQ(t.choice(), 1);
  // Way 1 measured cheaper still: kept.
  const std::vector<int> ways = run(t, 20, 5.0, 3.0);  // before the next retry
  for (int way : ways) EXPECT_EQ(way, 1);
}

TEST(TwoWayTuner, IgnoresBadCostsAndResetTriesBothAgain) {
  TwoWayTuner t;
  t.report(0, std::nan(""));
  t.report(0, -1.0);
  t.report(0, INFINITY);
  EXPECT_EQ(t.choice(), 0);
  EXPECT_LT(t.cost(0), 0.0);
  run(t, 5, 1.0, 2.0);
  EXPECT_EQ(t.choice(), 0);
  t.reset();
  EXPECT_EQ(t.choice(), 0);
  t.report(0, 1.0);
  EXPECT_EQ(t.choice(), 1);  // the other, untried since the reset
}

}  // namespace
}  // namespace ewa
