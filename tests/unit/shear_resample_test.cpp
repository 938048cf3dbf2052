// Sheared grids resampled within each slice: values stay where the file puts them in world.
#include "core/shear_resample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "io/volume_layout.h"

namespace ewa {
namespace {

// A field that bilinear sampling within a plane reproduces exactly: linear in world.
double linearField(const glm::dvec3& p) {
  return 2.0 * p.x - 3.0 * p.y + 0.5 * p.z + 10.0;
}

// A 6 x 5 x 4 float grid sheared both ways: the slices step obliquely (a gantry tilt of about
// 22 degrees) and the rows lean against the columns, each voxel holding linearField there.
struct ShearedGrid {
  std::vector<uint8_t> bytes;
  OrientedGrid grid;
  ShearedGrid() {
    grid.dims = {6, 5, 4};
    grid.spacing = {0.8, 0.6, 1.5};
    grid.origin = {3.0, -2.0, 7.0};
    grid.direction = glm::dmat3(glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(0.2, 1, 0)),
                                glm::normalize(glm::dvec3(0.1, 0.4, 1)));
    grid.elementSize = 4;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i) {
          const float v = float(linearField(world(glm::dvec3(i, j, k))));
          const auto* p = reinterpret_cast<const uint8_t*>(&v);
          bytes.insert(bytes.end(), p, p + 4);
        }
    grid.bytes = &bytes;
  }
  glm::dmat3 steps() const {
    return glm::dmat3(grid.direction[0] * grid.spacing.x, grid.direction[1] * grid.spacing.y,
                      grid.direction[2] * grid.spacing.z);
  }
  glm::dvec3 world(const glm::dvec3& ijk) const { return grid.origin + steps() * ijk; }
  glm::dvec3 index(const glm::dvec3& w) const { return glm::inverse(steps()) * (w - grid.origin); }
};

float floatAt(const std::vector<uint8_t>& b, size_t n) {
  float v;
  std::memcpy(&v, b.data() + 4 * n, 4);
  return v;
}

TEST(ShearResample, EveryVoxelHoldsTheFieldWhereItLiesInWorld) {
  ShearedGrid s;
  const ShearPlan plan = planShearResample(s.grid);
  ASSERT_TRUE(plan.ok) << plan.problem;
  EXPECT_TRUE(isOrthonormal(plan.direction, 1e-12));
  EXPECT_EQ(plan.dims[2], 4);  // the slices are kept
  EXPECT_GT(plan.dims[1], 5);  // spread over more rows by the tilt
  EXPECT_NEAR(plan.skewDegrees, std::acos(1.0 / glm::length(glm::dvec3(0.1, 0.4, 1))) * 57.29578,
              1e-3);
  const std::vector<uint8_t> out = resampleShear(plan, s.grid, ScalarType::Float32, -99.0);
  ASSERT_EQ(out.size(), size_t(plan.dims[0] * plan.dims[1] * plan.dims[2]) * 4);
  int inside = 0, outside = 0;
  for (int64_t k = 0; k < plan.dims[2]; ++k)
    for (int64_t j = 0; j < plan.dims[1]; ++j)
      for (int64_t i = 0; i < plan.dims[0]; ++i) {
        const glm::dvec3 w = plan.origin + plan.direction * (glm::dvec3(i, j, k) * plan.spacing);
        const glm::dvec3 old = s.index(w);
        EXPECT_NEAR(old.z, double(k), 1e-9);  // on its own slice, never between two
        const float v = floatAt(out, size_t(i + plan.dims[0] * (j + plan.dims[1] * k)));
        const bool in = old.x > -1e-7 && old.x < 5 + 1e-7 && old.y > -1e-7 && old.y < 4 + 1e-7;
        if (in) {
          ++inside;
          EXPECT_NEAR(v, linearField(w), 1e-3) << i << " " << j << " " << k;
        } else {
          ++outside;
          EXPECT_EQ(v, -99.0f) << i << " " << j << " " << k;
        }
      }
  EXPECT_GT(inside, 60);
  EXPECT_GT(outside, 20);
  // The upright grid covers every old voxel: its box holds their world positions.
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 5; j += 4)
      for (int i = 0; i < 6; i += 5) {
        const glm::dvec3 at = glm::transpose(plan.direction) *
                              (s.world(glm::dvec3(i, j, k)) - plan.origin) / plan.spacing;
        for (int a = 0; a < 3; ++a) {
          EXPECT_GT(at[a], -1e-9);
          EXPECT_LT(at[a], double(plan.dims[a] - 1) + 1e-9);
        }
      }
}

TEST(ShearResample, IntegersRoundAndUncoveredVoxelsTakeTheSmallestValue) {
  // Two slices of 3 x 2 uint8, the second moved by half a row: its samples fall midway.
  std::vector<uint8_t> bytes = {10, 20, 30, 41, 50, 60, 10, 20, 30, 41, 50, 60};
  OrientedGrid g;
  g.dims = {3, 2, 2};
  g.elementSize = 1;
  g.bytes = &bytes;
  g.spacing = {1.0, 2.0, std::sqrt(1.0 + 4.0)};
  g.direction = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0),
                           glm::normalize(glm::dvec3(0, 1, 2)));  // step (0, 1, 2)
  EXPECT_EQ(smallestValue(bytes, ScalarType::UInt8), 10.0);
  const ShearPlan plan = planShearResample(g);
  ASSERT_TRUE(plan.ok) << plan.problem;
  EXPECT_EQ(plan.dims, (std::array<int64_t, 3>{3, 3, 2}));  // y from 0 to 3 in steps of 2
  EXPECT_DOUBLE_EQ(plan.spacing.z, 2.0);
  const std::vector<uint8_t> out = resampleShear(plan, g, ScalarType::UInt8, 10.0);
  // New rows at y = 0, 2, 4. Slice 0 has rows at y = 0, 2; slice 1 (moved by 1) at y = 1, 3,
  // so its new row at y = 2 falls midway ((10 + 41) / 2 = 25.5, rounded 26) and those at 0 and
  // 4 fall outside it.
  const std::vector<uint8_t> expected = {10, 20, 30, 41, 50, 60, 10, 10, 10,   // slice 0
                                         10, 10, 10, 26, 35, 45, 10, 10, 10};  // slice 1
  EXPECT_EQ(out, expected);
}

TEST(ShearResample, RotationsAndHopelessShearsAreNotPlanned) {
  OrientedGrid g;
  g.dims = {4, 4, 100};
  EXPECT_FALSE(planShearResample(g).ok);  // the identity
  // Slices stepping almost within their own plane: each slice's row moves further than the
  // slice is wide, and the upright grid would hold many times the voxels.
  g.direction =
      glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0, 1, 0.1)));
  const ShearPlan steep = planShearResample(g);
  EXPECT_FALSE(steep.ok);
  EXPECT_NE(steep.problem.find("times the voxels"), std::string::npos) << steep.problem;
  g.direction = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1));
  EXPECT_FALSE(planShearResample(g).ok);  // two axes the same: degenerate
  // Rows 1e-100 apart: the growth, 1.75e101, is no integer (found by fuzzing NRRD headers).
  g.direction =
      glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0, 1, 1)));
  g.spacing = {1.0, 1e-100, 1.0};
  const ShearPlan huge = planShearResample(g);
  EXPECT_FALSE(huge.ok);
  EXPECT_NE(huge.problem.find("e+101 times the voxels"), std::string::npos) << huge.problem;
}

// Through makeVolume, where every loader's data becomes a Volume: resampled and said so, or
// (too sheared) kept with the nearest rotation's warning.
TEST(ShearResample, LoadersResampleOrWarn) {
  ShearedGrid s;
  VolumeLayout layout;
  layout.dims = s.grid.dims;
  layout.spacing = s.grid.spacing;
  layout.origin = s.grid.origin;
  layout.direction = s.grid.direction;
  layout.type = FileScalar::Float32;
  const Volume v = makeVolume("sheared.nrrd", layout, s.bytes);
  EXPECT_TRUE(isOrthonormal(v.direction(), 1e-12));
  ASSERT_EQ(v.notes().size(), 1u);
  EXPECT_NE(v.notes()[0].find("resampled within each slice onto 8 x"), std::string::npos)
      << v.notes()[0];
  // The value at the middle voxel is the field at its world position.
  const glm::dvec3 mid(v.dims()[0] / 2, v.dims()[1] / 2, 2);
  EXPECT_NEAR(v.value(int64_t(mid.x), int64_t(mid.y), 2),
              linearField(v.worldPosition(mid.x, mid.y, 2)), 1e-3);

  layout.dims = {4, 4, 100};
  layout.direction =
      glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0, 1, 0.1)));
  const Volume kept = makeVolume("steep.nrrd", layout, std::vector<uint8_t>(1600 * 4, 0));
  EXPECT_EQ(kept.dims()[2], 100);
  std::string notes;
  for (const std::string& n : kept.notes()) notes += n + "\n";
  EXPECT_NE(notes.find("not resampled"), std::string::npos) << notes;
  EXPECT_NE(notes.find("warning: the direction matrix is not orthonormal"), std::string::npos)
      << notes;
}

}  // namespace
}  // namespace ewa
