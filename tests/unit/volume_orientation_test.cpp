// Direction matrices: made rotations without moving voxels, kept by coarse levels, and the
// anatomical axis views of a patient frame.
#include "core/volume_orientation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/camera_views.h"
#include "core/volume_downsample.h"
#include "io/file_listing.h"

namespace ewa {
namespace {

// A 3 x 2 x 4 grid whose voxel (i,j,k) holds i + 3 j + 6 k.
std::vector<uint8_t> rampBytes() {
  std::vector<uint8_t> b(24);
  for (size_t n = 0; n < b.size(); ++n) b[n] = uint8_t(n);
  return b;
}

TEST(VolumeOrientation, ReflectionReversesSlicesKeepingWorldPositions) {
  std::vector<uint8_t> bytes = rampBytes();
  OrientedGrid g;
  g.dims = {3, 2, 4};
  g.bytes = &bytes;
  g.spacing = {1.0, 2.0, 3.0};
  g.origin = {10, 20, 30};
  g.direction =
      glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1));  // det -1
  const glm::dmat3 before = g.direction;
  const std::vector<std::string> notes = makeRotation(g);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("reflection"), std::string::npos);
  EXPECT_NEAR(glm::determinant(g.direction), 1.0, 1e-12);
  // Every voxel value sits where it sat: origin + D S ijk before and after.
  Volume v({3, 2, 4}, g.spacing, g.origin, ScalarType::UInt8, bytes);
  v.setDirection(g.direction, false);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const glm::dvec3 p = glm::dvec3(10, 20, 30) + before * (glm::dvec3(i, j, k) * g.spacing);
        const glm::dvec3 ijk = glm::transpose(v.direction()) * (p - v.origin()) / v.spacing();
        EXPECT_EQ(v.value(int64_t(std::lround(ijk.x)), int64_t(std::lround(ijk.y)),
                          int64_t(std::lround(ijk.z))),
                  i + 3 * j + 6 * k);
      }
}

TEST(VolumeOrientation, ShearIsOrthonormalizedWithAWarning) {
  OrientedGrid g;
  g.direction = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0.2, 0.98));
  const std::vector<std::string> notes = makeRotation(g);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("warning: ", 0), 0u);
  EXPECT_TRUE(isOrthonormal(g.direction, 1e-12));
  EXPECT_EQ(g.direction, glm::dmat3(1.0));  // Gram-Schmidt keeps the first two axes
  OrientedGrid r;                           // a rotation stays as it is, silently
  r.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
  EXPECT_TRUE(makeRotation(r).empty());
  EXPECT_EQ(r.direction[0], glm::dvec3(0, 1, 0));
  EXPECT_EQ(orthonormalized(glm::dmat3(0.0)), glm::dmat3(1.0));
}

// A header's huge entry (found by fuzzing a MetaImage TransformMatrix) must not overflow the
// lengths into a non-rotation: squared, 3.8e247 is not a double.
TEST(VolumeOrientation, HugeEntriesStillGiveARotation) {
  const glm::dmat3 d(glm::dvec3(1, 7.5e-16, 4.4e-16), glm::dvec3(7.5e-16, -1, 3.8e247),
                     glm::dvec3(0, 0, -1));
  const glm::dmat3 r = orthonormalized(d);
  EXPECT_TRUE(isOrthonormal(r, 1e-12));
  EXPECT_NEAR(r[0].x, 1.0, 1e-12);             // the first axis is kept
  EXPECT_NEAR(std::fabs(r[1].z), 1.0, 1e-12);  // the second points where its huge entry does
  for (double big : {1e200, 1e300, 1.7e308}) {
    const glm::dmat3 m(glm::dvec3(big, 0, 0), glm::dvec3(0, big, 1), glm::dvec3(0, 0, 1));
    EXPECT_TRUE(isOrthonormal(orthonormalized(m), 1e-12)) << big;
  }
}

TEST(VolumeOrientation, CameraInVolumeFrameUndoesTheRigidMap) {
  Volume v({3, 2, 4}, glm::dvec3(1.0), glm::dvec3(5, 0, 0), ScalarType::UInt8, rampBytes());
  v.setDirection(glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1)), true);
  Camera world;
  world.position = {5, 10, 0};  // 10 along world +y from the origin: data +x
  world.focalPoint = {5, 0, 0};
  world.viewUp = {-1, 0, 0};  // world -x: data +y
  const Camera local = cameraInVolumeFrame(world, v);
  EXPECT_NEAR(glm::length(local.position - glm::dvec3(15, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(local.focalPoint - glm::dvec3(5, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(local.viewUp - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
  // World bounds follow the direction: data x (3 voxels) lies along world y.
  EXPECT_EQ(v.worldBoundsMax() - v.worldBoundsMin(), glm::dvec3(1, 2, 3));
}

TEST(VolumeOrientation, CoarseLevelsKeepTheDirectionAndWorldBox) {
  Volume v({3, 2, 4}, glm::dvec3(1.0, 1.0, 2.0), glm::dvec3(1, 2, 3), ScalarType::UInt8,
           rampBytes());
  const glm::dmat3 d(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
  v.setDirection(d, true);
  const Volume coarse = downsampleVolume(v, 2);
  EXPECT_EQ(coarse.direction(), d);
  EXPECT_TRUE(coarse.patientFrame());
  // The first 2x2x2 block's centre, in world space.
  EXPECT_NEAR(glm::length(coarse.worldPosition(0, 0, 0) - v.worldPosition(0.5, 0.5, 0.5)), 0.0,
              1e-12);
}

TEST(VolumeOrientation, PatientFramesGetAnatomicalAxisViews) {
  EXPECT_STREQ(axisViewLabel(AxisView::PlusX, false), "+X");
  const char* expected[] = {"R", "L", "A", "P", "I", "S"};
  for (int n = 0; n < 6; ++n) EXPECT_STREQ(axisViewLabel(kAxisViews[n], true), expected[n]);
  // The anterior view: the eye on the anterior (-Y) side, superior (+Z) up.
  Camera c;
  const Camera a = initialVolumeView(c, glm::dvec3(-1), glm::dvec3(1), 1.0, true);
  EXPECT_LT(a.position.y, 0.0);
  EXPECT_NEAR(glm::length(glm::cross(a.viewUp, glm::dvec3(0, 0, 1))), 0.0, 1e-12);
  // Axial from above: anterior up; without a patient frame ParaView's +Y up.
  EXPECT_EQ(axisViewUp(AxisView::MinusZ, true), glm::dvec3(0, -1, 0));
  EXPECT_EQ(axisViewUp(AxisView::MinusZ, false), glm::dvec3(0, 1, 0));
  const Camera plain = initialVolumeView(c, glm::dvec3(-1), glm::dvec3(1), 1.0, false);
  EXPECT_GT(plain.position.z, 0.0);
}

TEST(VolumeOrientation, SlabsAreSeenThroughTheirFace) {
  // Three axial slices 12 mm apart over 500 mm: from the feet, anterior up, not edge on.
  Camera c;
  const glm::dvec3 lo(-250, -250, -18), hi(250, 250, 18);
  const Camera axial = initialVolumeView(c, lo, hi, 1.0, true);
  EXPECT_LT(axial.position.z, -100.0);
  EXPECT_NEAR(axial.position.x, 0.0, 1e-9);
  EXPECT_NEAR(axial.position.y, 0.0, 1e-9);
  EXPECT_EQ(axial.viewUp, glm::dvec3(0, -1, 0));
  // A sagittal slab from the patient's right (-X in LPS); a coronal one keeps the anterior view.
  const Camera sagittal =
      initialVolumeView(c, glm::dvec3(-5, -100, -100), glm::dvec3(5, 100, 100), 1.0, true);
  EXPECT_LT(sagittal.position.x, -50.0);
  EXPECT_NEAR(glm::length(glm::cross(sagittal.viewUp, glm::dvec3(0, 0, 1))), 0.0, 1e-12);
  const Camera coronal =
      initialVolumeView(c, glm::dvec3(-100, -5, -100), glm::dvec3(100, 5, 100), 1.0, true);
  EXPECT_LT(coronal.position.y, -50.0);
  // Without a patient frame: a slab thin in x is seen from +X; at a quarter it is no slab.
  const Camera thinX = initialVolumeView(c, glm::dvec3(0), glm::dvec3(4, 100, 100), 1.0, false);
  EXPECT_GT(thinX.position.x, 50.0);
  const Camera block = initialVolumeView(c, glm::dvec3(0), glm::dvec3(25, 100, 100), 1.0, false);
  EXPECT_GT(block.position.z, 50.0);
}

TEST(VolumeOrientation, OpenDialogListsTheNewFormats) {
  for (const char* name : {"a.nii", "b.NII.GZ", "c.hdr", "d.dcm", "e.tiff", "f.slc"})
    EXPECT_TRUE(hasExtension(name, volumeFileExtensions())) << name;
  EXPECT_FALSE(hasExtension("x.gz", volumeFileExtensions()));
}

}  // namespace
}  // namespace ewa
