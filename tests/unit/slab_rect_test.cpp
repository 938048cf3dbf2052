// slabPixelRect: every pixel a kernel listed in a slab can draw lies inside the slab's
// rectangle (random views, both projections, EWA and Swan, three kernel widths), and the
// rectangle is much smaller than the image where the volume is.
#include "core/slab_rect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "core/ewa_footprint.h"

namespace ewa {
namespace {

TEST(SlabRect, UniteAndEmpty) {
  const PixelRect a{1, 2, 5, 6}, b{3, 0, 9, 4}, none{};
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(a.area(), 16);
  const PixelRect u = a.unite(b);
  EXPECT_EQ(u.x0, 1);
  EXPECT_EQ(u.y0, 0);
  EXPECT_EQ(u.x1, 9);
  EXPECT_EQ(u.y1, 6);
  EXPECT_EQ(none.unite(a).area(), a.area());
  EXPECT_EQ(a.unite(none).area(), a.area());
}

TEST(SlabRect, HoldsEveryFootprintOfTheKernelsASlabLists) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const glm::dvec3 spacing(0.5 + unit(rng), 0.5 + unit(rng), 0.5 + 2.0 * unit(rng));
    const glm::dvec3 boxMax =
        glm::dvec3(20 + 40 * unit(rng), 20 + 40 * unit(rng), 10 + 30 * unit(rng)) * spacing;
    Camera cam;
    cam.orthographic = trial % 3 == 0;
    cam.viewAngleDeg = 20.0 + 30.0 * unit(rng);
    const glm::dvec3 dir = glm::normalize(
        glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) + glm::dvec3(1e-3));
    cam.focalPoint = boxMax * (0.2 + 0.6 * unit(rng));
    // From close (the near slabs nearly at the eye) to far (the volume a few pixels wide).
    cam.position = cam.focalPoint + dir * glm::length(boxMax) * (0.6 + 6.0 * unit(rng));
    cam.viewUp = std::abs(dir.y) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const Projection proj = cam.projection(160 + trial % 7 * 20, 120 + trial % 5 * 30);
    const FilterMode filter = trial % 4 == 1 ? FilterMode::Swan : FilterMode::Ewa;
    const double width = (trial % 3 == 0) ? 0.6 : (trial % 3 == 1 ? 1.0 : 1.6);
    const KernelReach reach = kernelReach(proj, filter, 4.0, spacing, width);
    FootprintParams params;
    params.filter = filter;
    params.minSpacing = std::min({spacing.x, spacing.y, spacing.z});
    params.cullDepth = 0.5 * params.minSpacing;
    const glm::dmat4 view = cam.viewMatrix();
    const glm::dmat3 cov = cameraCovariance(cam.rotation(), kernelSigma(spacing, width));
    const double thickness = 2.0 * params.minSpacing;
    // Slabs as the partition makes them: from the nearest kernel extent, `thickness` deep.
    double firstLo = INFINITY;
    std::vector<glm::dvec3> centers;
    for (int n = 0; n < 300; ++n) {
      const glm::dvec3 p =
          n < 8 ? glm::dvec3((n & 1) ? boxMax.x : 0, (n & 2) ? boxMax.y : 0, (n & 4) ? boxMax.z : 0)
                : boxMax * glm::dvec3(unit(rng), unit(rng), unit(rng));
      const glm::dvec3 u(view * glm::dvec4(p, 1.0));
      if (!(-u.z > params.cullDepth)) continue;
      centers.push_back(u);
      firstLo = std::min(firstLo, -u.z - depthReach(reach, cov[2][2], -u.z));
    }
    for (const glm::dvec3& u : centers) {
      const double d = -u.z, r = depthReach(reach, cov[2][2], d);
      const Footprint fp = computeFootprint(u, cov, proj, params);
      if (!fp.visible) continue;
      for (int s = int(std::floor((d - r - firstLo) / thickness));
           s <= int(std::floor((d + r - firstLo) / thickness)); ++s) {
        const double zn = firstLo + s * thickness;
        const PixelRect rect = slabPixelRect(view, proj, reach, glm::dvec3(0.0), boxMax, zn,
                                             zn + thickness, params.cullDepth);
        // Pixels i whose centre i + 0.5 lies within the footprint's radius must be inside.
        const double lo[2] = {fp.center.x - fp.radius, fp.center.y - fp.radius};
        const double hi[2] = {fp.center.x + fp.radius, fp.center.y + fp.radius};
        const int size[2] = {proj.width, proj.height};
        const int r0[2] = {rect.x0, rect.y0}, r1[2] = {rect.x1, rect.y1};
        for (int axis = 0; axis < 2; ++axis) {
          const int first = std::max(0, int(std::ceil(lo[axis] - 0.5)));
          const int last = std::min(size[axis] - 1, int(std::floor(hi[axis] - 0.5)));
          if (first > last) continue;  // off the image
          ASSERT_GE(first, r0[axis]) << "trial " << trial << " slab " << s << " axis " << axis;
          ASSERT_LT(last, r1[axis]) << "trial " << trial << " slab " << s << " axis " << axis;
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20000);
}

TEST(SlabRect, SmallWhereTheVolumeIsSmallAndEmptyBeyondIt) {
  // A 64^3 volume seen head-on from far: it covers a small middle part of a 512^2 image.
  Camera cam;
  cam.focalPoint = glm::dvec3(32.0);
  cam.position = cam.focalPoint + glm::dvec3(0.0, 0.0, 600.0);
  const Projection proj = cam.projection(512, 512);
  const KernelReach reach = kernelReach(proj, FilterMode::Ewa, 4.0, glm::dvec3(1.0));
  const glm::dmat4 view = cam.viewMatrix();
  const PixelRect middle =
      slabPixelRect(view, proj, reach, glm::dvec3(0.0), glm::dvec3(64.0), 598.0, 600.0, 0.5);
  EXPECT_FALSE(middle.empty());
  EXPECT_LT(middle.area(), 512 * 512 / 8);
  EXPECT_LT(std::abs(0.5 * (middle.x0 + middle.x1) - 256.0), 2.0);
  // Slabs beyond the volume's depth range (with the kernels' reach) have nothing to draw.
  EXPECT_TRUE(slabPixelRect(view, proj, reach, glm::dvec3(0.0), glm::dvec3(64.0), 700.0, 702.0, 0.5)
                  .empty());
  // Nothing of the box is near the eye plane: a slab there is empty; with the eye inside the
  // volume the first slab's kernels come close to the eye and may cover the whole image.
  EXPECT_TRUE(slabPixelRect(view, proj, reach, glm::dvec3(0.0), glm::dvec3(64.0), -10.0, 1.0, 1e-3)
                  .empty());
  Camera inside = cam;
  inside.position = glm::dvec3(32.0, 32.0, 40.0);
  const PixelRect first = slabPixelRect(inside.viewMatrix(), proj, reach, glm::dvec3(0.0),
                                        glm::dvec3(64.0), 0.5, 2.5, 0.5);
  EXPECT_EQ(first.area(), 512 * 512);
}

}  // namespace
}  // namespace ewa
