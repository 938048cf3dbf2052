// The bricks' visibility order (src/dist/visibility_order.h): along every sampled ray from the
// eye (perspective) or along the view (orthographic), a brick the ray enters first comes first;
// the eye's index coordinates follow the volume's origin, spacing and direction.
#include "dist/visibility_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

namespace ewa::dist {
namespace {

// Where the ray p + t d (t >= 0) enters the brick's box [low - 0.5, high - 0.5], or -1 when it
// misses it (or only grazes it).
double entry(const VoxelBox& b, const glm::dvec3& p, const glm::dvec3& d) {
  double t0 = 0.0, t1 = 1e300;
  for (int a = 0; a < 3; ++a) {
    const double lo = double(b.low[a]) - 0.5, hi = double(b.high[a]) - 0.5;
    if (d[a] == 0.0) {
      if (p[a] <= lo || p[a] >= hi) return -1.0;
      continue;
    }
    double u = (lo - p[a]) / d[a], v = (hi - p[a]) / d[a];
    if (u > v) std::swap(u, v);
    t0 = std::max(t0, u);
    t1 = std::min(t1, v);
  }
  return t1 - t0 > 1e-9 ? t0 : -1.0;
}

// For rays from `eye` (or, orthographic, parallel to `dir` from far behind) through random
// points of the box: bricks entered earlier are earlier in the order.
void expectOrderHolds(const BrickSplit& split, const std::array<int64_t, 3>& dims,
                      const IndexView& view, std::mt19937& rng) {
  const std::vector<int> order = visibilityOrder(split, view);
  ASSERT_EQ(order.size(), split.bricks.size());
  std::vector<int> place(order.size());
  for (size_t i = 0; i < order.size(); ++i) place[size_t(order[i])] = int(i);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 400; ++n) {
    const glm::dvec3 target(u(rng) * dims[0] - 0.5, u(rng) * dims[1] - 0.5, u(rng) * dims[2] - 0.5);
    glm::dvec3 p = view.eye, d = target - view.eye;
    if (view.orthographic) {
      d = view.direction;
      p = target - 1e4 * glm::normalize(d);
    }
    std::vector<std::pair<double, int>> hits;
    for (size_t b = 0; b < split.bricks.size(); ++b)
      if (!split.bricks[b].empty())
        if (double t = entry(split.bricks[b], p, d); t >= 0.0) hits.push_back({t, int(b)});
    std::sort(hits.begin(), hits.end());
    for (size_t h = 1; h < hits.size(); ++h)
      ASSERT_LT(place[size_t(hits[h - 1].second)], place[size_t(hits[h].second)])
          << "brick " << hits[h - 1].second << " is entered before " << hits[h].second;
  }
}

TEST(VisibilityOrder, PerspectiveRaysMeetBricksInOrder) {
  std::mt19937 rng(7);
  const std::array<int64_t, 3> dims{40, 33, 27};
  std::uniform_real_distribution<double> u(-60.0, 100.0);
  for (int parts : {2, 3, 5, 8, 11}) {
    const BrickSplit split = splitBricks(VoxelWeights(dims), parts);
    for (int e = 0; e < 12; ++e) {
      IndexView view;
      // Outside the box and inside it (the camera in the volume).
      view.eye = e < 3 ? glm::dvec3(u(rng) * 0.2 + 15, u(rng) * 0.2 + 12, u(rng) * 0.2 + 10)
                       : glm::dvec3(u(rng), u(rng), u(rng));
      SCOPED_TRACE(testing::Message() << parts << " bricks, eye " << view.eye.x << "," << view.eye.y
                                      << "," << view.eye.z);
      expectOrderHolds(split, dims, view, rng);
    }
  }
}

TEST(VisibilityOrder, OrthographicViewsMeetBricksInOrder) {
  std::mt19937 rng(11);
  const std::array<int64_t, 3> dims{24, 40, 31};
  std::normal_distribution<double> g(0.0, 1.0);
  for (int parts : {2, 3, 6, 9}) {
    const BrickSplit split = splitBricks(VoxelWeights(dims), parts);
    for (int e = 0; e < 10; ++e) {
      IndexView view;
      view.orthographic = true;
      view.direction = glm::dvec3(g(rng), g(rng), g(rng));
      if (e == 0) view.direction = glm::dvec3(0.0, 0.0, -1.0);  // along an axis: ties
      view.eye = glm::dvec3(12, 20, 15) - 100.0 * view.direction;
      SCOPED_TRACE(parts);
      expectOrderHolds(split, dims, view, rng);
    }
  }
}

TEST(VisibilityOrder, EyeInIndexCoordinatesFollowsTheVolumesPlacement) {
  Volume v({10, 20, 30}, glm::dvec3(0.5, 2.0, 1.0), glm::dvec3(100.0, -5.0, 3.0), ScalarType::UInt8,
           std::vector<uint8_t>(6000, 0));
  // Data axis x runs along world -y, y along world x, z along z.
  v.setDirection(glm::dmat3(glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)), false);
  Camera c;
  c.position = v.worldPosition(3.0, 4.0, 5.0);
  c.focalPoint = v.worldPosition(3.0, 4.0, 9.0);
  const IndexView view = indexView(c, v);
  EXPECT_NEAR(view.eye.x, 3.0, 1e-12);
  EXPECT_NEAR(view.eye.y, 4.0, 1e-12);
  EXPECT_NEAR(view.eye.z, 5.0, 1e-12);
  EXPECT_NEAR(view.direction.x, 0.0, 1e-12);
  EXPECT_NEAR(view.direction.y, 0.0, 1e-12);
  EXPECT_GT(view.direction.z, 0.0);
  // Two bricks cut across z at 15: the eye at z = 5 sees the lower one first.
  const BrickSplit split = splitBricks(VoxelWeights({10, 20, 30}), 2);
  EXPECT_EQ(visibilityOrder(split, view), (std::vector<int>{0, 1}));
  c.position = v.worldPosition(3.0, 4.0, 25.0);
  EXPECT_EQ(visibilityOrder(split, indexView(c, v)), (std::vector<int>{1, 0}));
}

}  // namespace
}  // namespace ewa::dist
