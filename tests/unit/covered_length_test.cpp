// Unit tests of post-classified slabs' covered length: the data's box, pixel rays in index
// coordinates, and the weight kept inside the box and dropped beyond it.
#include "core/covered_length.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/camera.h"
#include "core/volume.h"

namespace ewa {
namespace {

Volume volumeOf(std::array<int64_t, 3> dims, glm::dvec3 spacing, glm::dvec3 origin) {
  const size_t n = size_t(dims[0] * dims[1] * dims[2]);
  return Volume(dims, spacing, origin, ScalarType::UInt8, std::vector<uint8_t>(n, 100));
}

TEST(CoveredLength, DataBoxEndsAtTheOutermostVoxelCentres) {
  const DataBox box = volumeOf({5, 1, 3}, glm::dvec3(1.0), glm::dvec3(0.0)).indexDataBox();
  EXPECT_EQ(box.low, glm::dvec3(0.0, -0.5, 0.0));  // one voxel thick: that voxel's extent
  EXPECT_EQ(box.high, glm::dvec3(4.0, 0.5, 2.0));
}

TEST(CoveredLength, PixelRaysInIndexCoordinatesCrossTheBoxWhereTheyShould) {
  // Spacing 2 x 1 x 0.5 from origin (10, 0, -4): index = (world - origin) / spacing.
  const Volume v = volumeOf({11, 21, 41}, glm::dvec3(2.0, 1.0, 0.5), glm::dvec3(10, 0, -4));
  for (bool ortho : {false, true}) {
    Camera cam;
    cam.focalPoint = {20, 10, 6};  // the box's centre: index (5, 10, 20)
    cam.position = {20, 10, 46};   // 40 in front, looking down -z
    cam.orthographic = ortho;
    const Projection proj = cam.projection(64, 64);
    const IndexRay ray = indexRay(cameraToIndex(v, cam), proj, proj.principal);
    const glm::dvec3 centre = ray.origin + 40.0 * ray.direction;
    EXPECT_NEAR(centre.x, 5.0, 1e-9);
    EXPECT_NEAR(centre.y, 10.0, 1e-9);
    EXPECT_NEAR(centre.z, 20.0, 1e-9);
    // The box's z faces at world z -4 and 16: depths 50 and 30.
    const RayInterval in = boxDepths(ray.origin, ray.direction, v.indexDataBox());
    EXPECT_NEAR(in.near, 30.0, 1e-9);
    EXPECT_NEAR(in.far, 50.0, 1e-9);
    EXPECT_DOUBLE_EQ(rayStretch(proj, proj.principal), 1.0);
    // A pixel far off the image misses the box (20 world units wide).
    const IndexRay off = indexRay(cameraToIndex(v, cam), proj, glm::dvec2(-200.0, -200.0));
    EXPECT_TRUE(boxDepths(off.origin, off.direction, v.indexDataBox()).empty());
  }
}

TEST(CoveredLength, ObliqueRayLengthAndStretch) {
  // Perspective: the world length of a depth interval grows by |(q / f, -1)|.
  Projection proj;
  proj.focalPixels = 100.0;
  proj.principal = {50.0, 50.0};
  EXPECT_NEAR(rayStretch(proj, {80.0, 10.0}), std::sqrt(1.0 + 0.09 + 0.16), 1e-12);
  proj.orthographic = true;
  EXPECT_DOUBLE_EQ(rayStretch(proj, {80.0, 10.0}), 1.0);
}

TEST(CoveredLength, RayParallelToAFaceOutsideTheBoxCrossesNothing) {
  DataBox box;
  box.high = glm::dvec3(4.0);
  EXPECT_TRUE(boxDepths({-1.0, 2.0, 10.0}, {0.0, 0.0, -1.0}, box).empty());
  const RayInterval in = boxDepths({1.0, 2.0, 10.0}, {0.0, 0.0, -1.0}, box);
  EXPECT_DOUBLE_EQ(in.near, 6.0);
  EXPECT_DOUBLE_EQ(in.far, 10.0);
}

TEST(CoveredLength, KeepsTheWeightInsideDropsItOutsideAndCutsTailsAtAFace) {
  const RayInterval in{10.0, 20.0};
  // Wholly inside: the kernels' weight, whatever it is (their lattice sets it).
  EXPECT_DOUBLE_EQ(coveredLength(12.0, 12.5, in, 1.1, 0.49), 0.49);
  EXPECT_DOUBLE_EQ(coveredLength(12.0, 12.5, in, 1.1, 0.7), 0.7);
  // Wholly outside: nothing, though the kernels' tails reach there.
  EXPECT_DOUBLE_EQ(coveredLength(9.0, 9.5, in, 1.1, 0.3), 0.0);
  EXPECT_DOUBLE_EQ(coveredLength(20.0, 20.5, in, 1.1, 0.3), 0.0);
  // Cut by a face: at most the length inside (0.25 of depth, 1.1 world units a depth unit).
  EXPECT_DOUBLE_EQ(coveredLength(9.75, 10.25, in, 1.1, 0.5), 0.275);
  EXPECT_NEAR(coveredLength(19.9, 20.4, in, 1.0, 0.5), 0.1, 1e-12);
  // ... and no more than the kernels cover there.
  EXPECT_DOUBLE_EQ(coveredLength(9.75, 10.25, in, 1.1, 0.1), 0.1);
  // Empty box: nothing anywhere.
  EXPECT_DOUBLE_EQ(coveredLength(12.0, 12.5, RayInterval{1.0, 0.0}, 1.0, 0.5), 0.0);
}

}  // namespace
}  // namespace ewa
