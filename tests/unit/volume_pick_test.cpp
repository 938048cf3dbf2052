// Picking: pixel rays, the point a ray shows (opaque, translucent, cut, rotated, MIP) and the
// camera centred on it.
#include "core/volume_pick.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>

namespace ewa {
namespace {

constexpr int kN = 33;  // a 33^3 float grid, spacing 1, centre voxel (16, 16, 16)

// Float voxels from f(i, j, k).
template <class F>
Volume floatVolume(F f, glm::dvec3 spacing = glm::dvec3(1.0), glm::dvec3 origin = glm::dvec3(0.0)) {
  std::vector<uint8_t> bytes(size_t(kN) * kN * kN * sizeof(float));
  float* v = reinterpret_cast<float*>(bytes.data());
  for (int k = 0; k < kN; ++k)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) v[i + kN * (j + kN * k)] = float(f(i, j, k));
  return Volume({kN, kN, kN}, spacing, origin, ScalarType::Float32, std::move(bytes));
}

// 200 inside a ball of radius 10 about voxel (16, 16, 16), 0 outside.
Volume ball() {
  return floatVolume([](int i, int j, int k) {
    const double r2 = (i - 16.0) * (i - 16.0) + (j - 16.0) * (j - 16.0) + (k - 16.0) * (k - 16.0);
    return r2 <= 100.0 ? 200.0 : 0.0;
  });
}

// Transparent below 100, opaque from 110.
TransferFunction opaqueAbove100() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {100.0, 0.0}, {110.0, 1.0}, {255.0, 1.0}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}};
  return tf;
}

Camera lookingDownZ(glm::dvec3 focal = glm::dvec3(16.0)) {
  Camera c;
  c.focalPoint = focal;
  c.position = focal + glm::dvec3(0.0, 0.0, 80.0);
  c.viewUp = {0.0, 1.0, 0.0};
  return c;
}

// Where world point p lands in a width x height picture, in window coordinates (y down): the
// test's own projection, independent of windowPoint.
glm::dvec2 projectedByHand(const Camera& camera, int width, int height, const glm::dvec3& p) {
  const Projection proj = camera.projection(width, height);
  const glm::dvec3 c = glm::dvec3(camera.viewMatrix() * glm::dvec4(p, 1.0));
  const glm::dvec2 lateral = proj.orthographic ? glm::dvec2(c) * proj.pixelsPerUnit
                                               : glm::dvec2(c) / -c.z * proj.focalPixels;
  const glm::dvec2 pixel = proj.principal + lateral;
  return {pixel.x, double(height) - pixel.y};
}

double distanceToRay(const PickRay& ray, const glm::dvec3& p) {
  const glm::dvec3 d = glm::normalize(ray.direction);
  const glm::dvec3 v = p - ray.origin;
  return glm::length(v - glm::dot(v, d) * d);
}

TEST(VolumePick, PixelRaysPassThroughThePointsTheCameraProjectsThere) {
  for (bool orthographic : {false, true}) {
    Camera camera;
    camera.position = {30.0, -40.0, 25.0};
    camera.focalPoint = {2.0, 3.0, -1.0};
    camera.viewUp = {0.0, 0.0, 1.0};
    camera.viewAngleDeg = 40.0;
    camera.orthographic = orthographic;
    const int w = 320, h = 200;
    for (const glm::dvec3 p :
         {glm::dvec3(2.0, 3.0, -1.0), glm::dvec3(-5.0, 8.0, 4.0), glm::dvec3(10.0, 0.0, -9.0)}) {
      const glm::dvec2 at = projectedByHand(camera, w, h, p);
      ASSERT_GT(at.x, 0.0);
      ASSERT_LT(at.y, double(h));
      EXPECT_LT(distanceToRay(pickRay(camera, w, h, at), p), 1e-9) << orthographic;
      const std::optional<glm::dvec2> back = windowPoint(camera, w, h, p);  // the inverse
      ASSERT_TRUE(back.has_value());
      EXPECT_LT(glm::length(*back - at), 1e-9);
    }
    // The centre of the picture looks along the view direction; up in the picture is +view-up.
    // Behind the eye a perspective camera sees nothing; a parallel one sees every point.
    const glm::dvec3 behind = camera.position - camera.direction();
    EXPECT_EQ(windowPoint(camera, w, h, behind).has_value(), orthographic);
    const PickRay centre = pickRay(camera, w, h, {w / 2.0, h / 2.0});
    EXPECT_LT(glm::length(centre.direction - camera.direction()), 1e-12);
    const PickRay top = pickRay(camera, w, h, {w / 2.0, 0.5});
    const glm::dvec3 towardTop =
        orthographic ? top.origin - centre.origin : top.direction - centre.direction;
    EXPECT_GT(towardTop.z, 0.0);
  }
}

TEST(VolumePick, AnOpaqueBallIsPickedAtItsSurface) {
  const Volume v = ball();
  const Camera camera = lookingDownZ();
  const PickResult r =
      pickVolume(v, opaqueAbove100(), ClipRegion(), pickRay(camera, 100, 100, {50.0, 50.0}));
  ASSERT_TRUE(r.hit);
  // The field rises from 0 at z = 27 to 200 at z = 26 (the ball's top voxel): alpha 1 from value
  // 110, at z = 26.45, and that opaque a layer reaches half its opacity within 0.05 of it.
  EXPECT_NEAR(r.world.z, 26.43, 0.06);
  EXPECT_NEAR(r.world.x, 16.0, 1e-9);
  EXPECT_NEAR(r.value, 110.0, 12.0);
  EXPECT_NEAR(r.opacity, 1.0, 1e-6);
  EXPECT_LT(glm::length(r.index - r.world), 1e-9);  // identity placement
  EXPECT_NEAR(r.distance, 80.0 - 10.43, 0.06);
}

TEST(VolumePick, RaysThatShowNothingPickNothing) {
  const Volume v = ball();
  const Camera camera = lookingDownZ();
  // A corner of the box, outside the ball: only zeros along the ray.
  EXPECT_FALSE(
      pickVolume(v, opaqueAbove100(), ClipRegion(), pickRay(camera, 100, 100, {30, 30})).hit);
  // Past the box entirely, and a ray pointing away from it.
  EXPECT_FALSE(
      pickVolume(v, opaqueAbove100(), ClipRegion(), pickRay(camera, 100, 100, {1, 1})).hit);
  EXPECT_FALSE(
      pickVolume(v, opaqueAbove100(), ClipRegion(), PickRay{{16.0, 16.0, 40.0}, {0.0, 0.0, 1.0}})
          .hit);
  // A transparent function, and a ray whose total opacity stays under the minimum.
  TransferFunction clear = opaqueAbove100();
  for (OpacityPoint& p : clear.opacity) p.alpha = 0.0;
  EXPECT_FALSE(pickVolume(v, clear, ClipRegion(), pickRay(camera, 100, 100, {50, 50})).hit);
  TransferFunction faint = clear;
  faint.opacity = {{0.0, 0.0}, {100.0, 0.0}, {110.0, 0.0002}, {255.0, 0.0002}};
  EXPECT_FALSE(pickVolume(v, faint, ClipRegion(), pickRay(camera, 100, 100, {50, 50})).hit);
}

TEST(VolumePick, AHazeIsPickedWhereItsOpacityReachesHalfItsTotal) {
  // Value 50 everywhere, extinction tau per unit: along z through the box (length 32) the
  // opacity grows as 1 - e^(-tau x); half of the total is reached at x = -ln((1 + e^-32tau)/2)/tau.
  const Volume v = floatVolume([](int, int, int) { return 50.0; });
  TransferFunction tf;
  tf.opacity = {{0.0, 0.05}, {255.0, 0.05}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}};
  const double tau = -std::log(1.0 - 0.05);
  const double x = -std::log(0.5 * (1.0 + std::exp(-32.0 * tau))) / tau;
  const PickResult r =
      pickVolume(v, tf, ClipRegion(), pickRay(lookingDownZ(), 64, 64, {32.0, 32.0}));
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.world.z, 32.0 - x, 1e-6);
  EXPECT_NEAR(r.opacity, 1.0 - std::exp(-32.0 * tau), 1e-9);
  EXPECT_DOUBLE_EQ(r.value, 50.0);
}

TEST(VolumePick, ACropBoxCutsTheBallOpen) {
  const Volume v = ball();
  ClipRegion crop;
  crop.cropEnabled = true;
  crop.cropMin = {0.0, 0.0, 0.0};
  crop.cropMax = {32.0, 32.0, 20.0};  // the ball's top from z = 20 up is cut away
  const PickResult r =
      pickVolume(v, opaqueAbove100(), crop, pickRay(lookingDownZ(), 100, 100, {50.0, 50.0}));
  ASSERT_TRUE(r.hit);
  // Just under the cut face: the opaque inside (extinction 13.8 a unit) halves the light in 0.05.
  EXPECT_NEAR(r.world.z, 20.0 - std::log(2.0) / -std::log(1e-6), 1e-3);
  EXPECT_DOUBLE_EQ(r.value, 200.0);
}

TEST(VolumePick, ARotatedPlacedVolumeGivesItsOwnIndexAndTheWorldPoint) {
  // Spacing 2, origin (100, 0, 0), axes turned 90 degrees about z: data x runs along world y.
  Volume v = floatVolume(
      [](int i, int j, int k) {
        const double r2 =
            (i - 16.0) * (i - 16.0) + (j - 16.0) * (j - 16.0) + (k - 16.0) * (k - 16.0);
        return r2 <= 100.0 ? 200.0 : 0.0;
      },
      glm::dvec3(2.0), glm::dvec3(100.0, 0.0, 0.0));
  v.setDirection(glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1)), false);
  const glm::dvec3 centre = v.worldPosition(16.0, 16.0, 16.0);
  Camera camera = lookingDownZ(centre);
  camera.position = centre + glm::dvec3(0.0, 0.0, 200.0);
  const PickResult r =
      pickVolume(v, opaqueAbove100(), ClipRegion(), pickRay(camera, 100, 100, {50.0, 50.0}));
  ASSERT_TRUE(r.hit);
  EXPECT_LT(glm::length(v.worldPosition(r.index.x, r.index.y, r.index.z) - r.world), 1e-9);
  EXPECT_NEAR(r.index.x, 16.0, 1e-9);
  EXPECT_NEAR(r.index.y, 16.0, 1e-9);
  EXPECT_NEAR(r.index.z, 26.43, 0.06);
  EXPECT_NEAR(r.world.z, centre.z + 2.0 * 10.43, 0.12);
}

TEST(VolumePick, MaximumIntensityPicksTheBrightestPoint) {
  const Volume v = floatVolume([](int i, int j, int k) {
    if (j == 16 && k == 16 && i == 7) return 90.0;
    if (j == 16 && k == 16 && i == 25) return 60.0;
    return 5.0;
  });
  // Along +x through row (16, 16): the brightest voxel is i = 7, however opaque it is.
  TransferFunction faint;
  faint.opacity = {{0.0, 0.0}, {50.0, 0.001}, {255.0, 0.001}};
  const PickRay row{{-10.0, 16.0, 16.0}, {1.0, 0.0, 0.0}};
  const PickResult r = pickVolume(v, faint, ClipRegion(), row, PickRule::MaximumValue);
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.index.x, 7.0, 0.13);
  EXPECT_NEAR(r.value, 90.0, 5.0);
  // Values the function hides are not drawn, so not picked: with 50 to 62 shown, 60 at i = 25 is
  // the brightest (the samples around i = 7 step from 47.5 to 68.75).
  TransferFunction band = faint;
  band.opacity = {{0.0, 0.0}, {50.0, 0.001}, {62.0, 0.001}, {62.5, 0.0}, {255.0, 0.0}};
  const PickResult shown = pickVolume(v, band, ClipRegion(), row, PickRule::MaximumValue);
  ASSERT_TRUE(shown.hit);
  EXPECT_NEAR(shown.index.x, 25.0, 0.13);
  TransferFunction clear;
  clear.opacity = {{0.0, 0.0}, {255.0, 0.0}};
  EXPECT_FALSE(pickVolume(v, clear, ClipRegion(), row, PickRule::MaximumValue).hit);
}

TEST(VolumePick, NaNVoxelsAreTransparentAndHugeRaysStayBounded) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Volume v =
      floatVolume([nan](int, int, int k) { return k > 20 ? double(nan) : (k < 8 ? 200.0 : 0.0); });
  const PickResult r =
      pickVolume(v, opaqueAbove100(), ClipRegion(), pickRay(lookingDownZ(), 64, 64, {32, 32}));
  ASSERT_TRUE(r.hit);  // through the NaN slices to the opaque bottom
  EXPECT_NEAR(r.world.z, 7.43, 0.06);
  EXPECT_TRUE(std::isfinite(r.value));
  // A tiny spacing along one axis and a huge one along the others: steps are capped.
  const Volume thin = floatVolume([](int, int, int) { return 200.0; }, glm::dvec3(1e6, 1e6, 1e-6));
  const PickResult far = pickVolume(thin, opaqueAbove100(), ClipRegion(),
                                    PickRay{{-1e7, 1.6e7, 1.6e-5}, {1.0, 0.0, 0.0}});
  EXPECT_TRUE(far.hit);
}

TEST(VolumePick, DescriptionNamesThePointTheNearestVoxelTheValueAndTheMarksDistance) {
  const Volume v = ball();
  PickResult pick;
  EXPECT_EQ(describePick(v, pick), "");  // a miss says nothing
  pick.hit = true;
  pick.world = {12.5, -3.25, 40.0};
  pick.index = {16.4, 15.6, 40.7};  // past the grid's last slice: the nearest voxel is inside
  pick.value = 87.25;
  EXPECT_EQ(describePick(v, pick), "x 12.5  y -3.25  z 40   voxel 16, 16, 32   value 87.25");
  EXPECT_EQ(describePick(v, pick, glm::dvec3(12.5, 0.75, 43.0)),
            "x 12.5  y -3.25  z 40   voxel 16, 16, 32   value 87.25   5 from the mark");
  // Patient axes are named.
  Volume patient = ball();
  patient.setDirection(glm::dmat3(1.0), true);
  EXPECT_EQ(describePick(patient, pick),
            "x 12.5  y -3.25  z 40 (LPS)   voxel 16, 16, 32   value 87.25");
  // Lengths in the file's unit, when it names one.
  patient.setUnit("mm");
  EXPECT_EQ(describePick(patient, pick, glm::dvec3(12.5, 0.75, 43.0)),
            "x 12.5  y -3.25  z 40 mm (LPS)   voxel 16, 16, 32   value 87.25   5 mm from the mark");
}

TEST(VolumePick, CentringKeepsTheViewDirectionAndThePointsDepth) {
  Camera camera = lookingDownZ();
  camera.position = {20.0, 10.0, 90.0};
  const glm::dvec3 p(5.0, 22.0, 30.0);
  const Camera c = centredOn(camera, p);
  EXPECT_LT(glm::length(c.focalPoint - p), 1e-12);
  EXPECT_LT(glm::length(c.direction() - camera.direction()), 1e-12);
  EXPECT_NEAR(c.distance(), glm::dot(p - camera.position, camera.direction()), 1e-9);
  EXPECT_EQ(c.viewUp, camera.viewUp);
  // Parallel projection: the distance, hence the scale, is kept.
  camera.orthographic = true;
  EXPECT_NEAR(centredOn(camera, p).distance(), camera.distance(), 1e-9);
  // A point behind the eye keeps the old distance instead of flipping the view.
  camera.orthographic = false;
  const Camera behind = centredOn(camera, camera.position - 5.0 * camera.direction());
  EXPECT_NEAR(behind.distance(), camera.distance(), 1e-9);
  EXPECT_LT(glm::length(behind.direction() - camera.direction()), 1e-12);
}

}  // namespace
}  // namespace ewa
