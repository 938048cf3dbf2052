// TwoWayTuner: both ways tried first, then the cheaper kept, the other retried every kRetryEvery.
#include "core/two_way_tuner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
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
  // Costs a fifth apart: the other way retried after kRetryEvery frames of the cheaper.
  TwoWayTuner t;
  const std::vector<int> ways = run(t, 2 + 2 * (TwoWayTuner::kRetryEvery + 1), 1.2, 1.0);
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
  EXPECT_DOUBLE_EQ(t.cost(0), 1.2);
  EXPECT_DOUBLE_EQ(t.cost(1), 1.0);
}

// Way 1 tried first where asked (the compute tiles on a GPU), then way 0, then the cheaper kept.
TEST(TwoWayTuner, TriesTheWayAskedForFirst) {
  TwoWayTuner t(1);
  const std::vector<int> ways = run(t, 4, 1.0, 1.2);
  EXPECT_EQ(ways, (std::vector<int>{1, 0, 0, 0}));
  t.reset();
  EXPECT_EQ(t.choice(), 1) << "a reset tries the first way first again";
}

// A way r times dearer is retried after kRetryEvery * (r - 1) frames (at least kRetryEvery, at
// most kMaxRetryEvery), so the retries' share of the time stays under 1/kRetryEvery up to the
// cap: 2x apart every 32 frames, 5x every 128, 20x every 256.
TEST(TwoWayTuner, RetriesADearerWayLessOften) {
  for (const auto& [dear, every] :
       {std::pair{2.0, 32}, std::pair{5.0, 128}, std::pair{20.0, 256}}) {
    SCOPED_TRACE(dear);
    TwoWayTuner t;
    const int frames = 2 + 3 * (every + 1);
    const std::vector<int> ways = run(t, frames, dear, 1.0);
    EXPECT_EQ(t.retryEvery(), every);
    std::vector<int> retries;
    for (int i = 2; i < frames; ++i)
      if (ways[size_t(i)] == 0) retries.push_back(i);
    ASSERT_EQ(retries.size(), 3u);
    EXPECT_EQ(retries[0], 2 + every);
    EXPECT_EQ(retries[1] - retries[0], every + 1);
    double time = 0.0;
    for (int way : ways) time += way == 0 ? dear : 1.0;
    const double retryShare = 3.0 * (dear - 1.0) / time;
    EXPECT_LT(retryShare, dear > 8.0 ? 0.08 : 1.0 / TwoWayTuner::kRetryEvery) << retryShare;
  }
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
