// The benchmarks' compute tile splatter against a C++ sum of the same footprints: every pixel of
// both tile sizes, with footprints across tile borders, beyond the picture's edges and piled
// many deep in one tile (more than one batch of the group's shared memory).
#include "bench/tile_splat_baseline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/ewa_footprint.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class TileSplatBaselineTest : public RenderFixture {};

struct Case {
  Footprint fp;
  TileFootprint tile;
};

// A footprint of covariance [[a, b], [b, c]] (pixels^2) centred at (x, y), peak `peak`.
Case footprint(double x, double y, double a, double b, double c, double peak, double cutoff) {
  Case k;
  k.fp.visible = true;
  k.fp.center = glm::dvec2(x, y);
  k.fp.covariance = glm::dmat2(a, b, b, c);
  k.fp.conic = glm::inverse(k.fp.covariance);
  k.fp.peak = peak;
  k.tile.box = glm::vec4(x, y, std::sqrt(cutoff * a), std::sqrt(cutoff * c));
  k.tile.conic = glm::vec4(k.fp.conic[0][0], k.fp.conic[0][1], k.fp.conic[1][1], peak);
  return k;
}

TEST_F(TileSplatBaselineTest, SumsEveryFootprintAtEveryPixelAsTheCppFootprintDoes) {
  const int width = 45, height = 37;  // not multiples of either tile size
  const double cutoff = 5.0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-6.0, 51.0), var(0.3, 9.0), corr(-0.8, 0.8);
  std::vector<Case> cases;
  for (int n = 0; n < 300; ++n) {
    const double a = var(rng), c = var(rng), b = corr(rng) * std::sqrt(a * c);
    cases.push_back(footprint(pos(rng), pos(rng) * height / width, a, b, c, 1.0 + n % 3, cutoff));
  }
  // Many deep in the tile at the origin (more than a 16 x 16 group's batch of 256), and one on
  // a tile corner reaching four tiles.
  for (int n = 0; n < 600; ++n) cases.push_back(footprint(3.1, 4.7, 2.0, 0.5, 1.5, 0.01, cutoff));
  cases.push_back(footprint(16.0, 16.0, 6.0, 0.0, 6.0, 3.0, cutoff));
  std::vector<TileFootprint> tiles;
  for (const Case& k : cases) tiles.push_back(k.tile);
  for (int tileSize : {8, 16}) {
    TileSplatBaseline baseline(gl::ShaderLibrary(), tileSize);
    baseline.setFootprints(tiles, float(cutoff));
    baseline.draw(20, 17, false);  // a smaller picture first: the buffers then grow
    for (bool halfFloat : {false, true}) {
      const TileSplatBaseline::Timing t = baseline.draw(width, height, halfFloat);
      EXPECT_GT(t.entries, cases.size()) << "some footprints reach several tiles";
      const std::vector<glm::vec4> image = baseline.frontImage();
      ASSERT_EQ(image.size(), size_t(width * height));
      int covered = 0;
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          double want = 0.0;
          for (const Case& k : cases)
            want += footprintWeight(k.fp, glm::dvec2(x + 0.5, y + 0.5), cutoff);
          const glm::vec4 got = image[size_t(y * width + x)];
          const double tolerance = (halfFloat ? 2e-3 : 1e-4) * want + 1e-5;
          ASSERT_NEAR(got.y, want, tolerance) << "pixel " << x << "," << y << " tile " << tileSize
                                              << (halfFloat ? " half" : " float");
          ASSERT_NEAR(got.x, 0.5 * want, tolerance) << "pixel " << x << "," << y;
          covered += want > 0.0;
        }
      }
      EXPECT_GT(covered, width * height / 2);
    }
  }
}

// Seventy thousand footprints over one tile: every one is added (llvmpipe ends a shader's loops
// after 65535 iterations in all, which one footprint an iteration reached: tiles_ms on llvmpipe
// then left out part of its busiest tiles' work).
TEST_F(TileSplatBaselineTest, AddsEveryFootprintOfABusyTile) {
  const int size = 16;
  const double cutoff = 5.0;
  const Case k = footprint(8.0, 8.0, 60.0, 0.0, 60.0, 1e-4, cutoff);
  const std::vector<TileFootprint> tiles(70000, k.tile);
  for (int tileSize : {8, 16}) {
    TileSplatBaseline baseline(gl::ShaderLibrary(), tileSize);
    baseline.setFootprints(tiles, float(cutoff));
    baseline.draw(size, size, false);
    const std::vector<glm::vec4> image = baseline.frontImage();
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const double want =
            double(tiles.size()) * footprintWeight(k.fp, glm::dvec2(x + 0.5, y + 0.5), cutoff);
        ASSERT_NEAR(image[size_t(y * size + x)].y, want, 1e-3 * want)
            << x << "," << y << " tile " << tileSize;
      }
  }
}

}  // namespace
}  // namespace ewa::test
