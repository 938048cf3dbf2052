// Unit tests of the crop box and clipping planes: parsing, half-spaces, clipped rays, the
// clipped share of a kernel along a pixel ray, and shear-warp's kept cells.
#include "core/clip_region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "core/clip_share.h"
#include "core/ewa_footprint.h"
#include "core/shear_warp.h"
#include "core/shear_warp_clip.h"
#include "core/synthetic_volume.h"

namespace ewa {
namespace {

TEST(ClipRegion, ParsesBoxAndPlanes) {
  ClipRegion r;
  EXPECT_EQ(parseCropBox("0,10,-2.5,3,1e1,20", &r), "");
  EXPECT_TRUE(r.cropEnabled);
  EXPECT_EQ(r.cropMin, glm::dvec3(0, -2.5, 10));
  EXPECT_EQ(r.cropMax, glm::dvec3(10, 3, 20));
  EXPECT_EQ(parseClipPlane("1,2,3,0,0,-2", &r), "");
  ASSERT_EQ(r.planes.size(), 1u);
  EXPECT_EQ(r.planes[0].point, glm::dvec3(1, 2, 3));
  EXPECT_TRUE(r.active());
  EXPECT_EQ(r.halfSpaces().size(), 7u);
}

TEST(ClipRegion, RejectsMalformedText) {
  ClipRegion r;
  EXPECT_NE(parseCropBox("0,10,0,10,0", &r).find("expected 6"), std::string::npos);
  EXPECT_NE(parseCropBox("0,10,0,10,0,x", &r).find("'x' is not a finite number"),
            std::string::npos);
  EXPECT_NE(parseCropBox("0,10,0,10,0,10,", &r).find("missing"), std::string::npos);
  EXPECT_NE(parseCropBox("0,10,5,5,0,10", &r).find("Y0 must be less than Y1"), std::string::npos);
  EXPECT_NE(parseCropBox("0,inf,0,1,0,1", &r).find("not a finite"), std::string::npos);
  EXPECT_FALSE(r.cropEnabled);
  EXPECT_NE(parseClipPlane("0,0,0,0,0,0", &r).find("normal is zero"), std::string::npos);
  EXPECT_NE(parseClipPlane("0,0,0,1,0", &r).find("expected 6"), std::string::npos);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(parseClipPlane("0,0,0,1,0,0", &r), "");
  EXPECT_NE(parseClipPlane("0,0,0,1,0,0", &r).find("at most 6"), std::string::npos);
  EXPECT_EQ(r.planes.size(), 6u);
}

TEST(ClipRegion, ContainsAndClipsRaysConsistently) {
  ClipRegion r;
  r.cropEnabled = true;
  r.cropMin = {-1, -2, -3};
  r.cropMax = {4, 5, 6};
  r.planes.push_back({glm::dvec3(1, 1, 1), glm::dvec3(1, -1, 0.5), true});
  r.planes.push_back({glm::dvec3(0), glm::dvec3(0, 0, 1), false});  // off: ignored
  EXPECT_TRUE(r.contains({2, 1, 0}));
  EXPECT_FALSE(r.contains({2, 1, -4}));  // below the box
  EXPECT_FALSE(r.contains({0, 3, 0}));   // behind the plane
  EXPECT_TRUE(r.contains({2, 0, -2}));   // the switched-off plane would drop it
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 200; ++n) {
    const glm::dvec3 o(5 * u(rng), 5 * u(rng), 5 * u(rng));
    const glm::dvec3 d(u(rng), u(rng), u(rng));
    const RayInterval span = r.clipRay(o, d, -20.0, 20.0);
    for (double t = -20.0; t <= 20.0; t += 0.173) {
      const bool inside = !span.empty() && t >= span.near && t <= span.far;
      const glm::dvec3 x = o + t * d;
      // Away from the boundary (rounding) the two must agree.
      double margin = 1e9;
      for (const HalfSpace& h : r.halfSpaces()) margin = std::min(margin, std::fabs(h.distance(x)));
      if (margin > 1e-9) {
        EXPECT_EQ(inside, r.contains(x)) << n << " t " << t;
      }
    }
  }
}

TEST(ClipRegion, HalfSpacesFollowRigidMaps) {
  const HalfSpace h{glm::normalize(glm::dvec3(1, 2, -1)), 0.7};
  const glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(3, -1, 2)) *
                       glm::rotate(glm::dmat4(1.0), 0.8, glm::normalize(glm::dvec3(1, 1, 0)));
  const HalfSpace t = transformed(h, m);
  for (const glm::dvec3 x : {glm::dvec3(0), glm::dvec3(1, -2, 5), glm::dvec3(-3, 4, 1)})
    EXPECT_NEAR(t.distance(glm::dvec3(m * glm::dvec4(x, 1.0))), h.distance(x), 1e-12);
}

TEST(ClipShare, DepthIntervalIsThePixelRaysPartInside) {
  // Camera-space half-spaces against points on the ray through a pixel, both projections.
  const std::vector<HalfSpace> planes = {
      {glm::normalize(glm::dvec3(0.3, -0.2, -1.0)), -4.0},  // depth >= about 4
      {glm::normalize(glm::dvec3(0.5, 0.4, 1.0)), 9.0},     // depth <= about 9
      {glm::normalize(glm::dvec3(1.0, 0.0, 0.0)), 0.5},     // x >= -0.5
  };
  for (bool ortho : {false, true}) {
    Projection proj;
    proj.orthographic = ortho;
    proj.focalPixels = 80.0;
    proj.pixelsPerUnit = 12.0;
    proj.principal = {32, 24};
    for (const glm::dvec2 pixel :
         {glm::dvec2(32.5, 24.5), glm::dvec2(3.5, 40.5), glm::dvec2(60, 2)}) {
      const RayInterval kept = clippedDepths(planes, proj, pixel);
      const glm::dvec2 q = pixel - proj.principal;
      for (double z = 0.05; z < 15.0; z += 0.05) {
        const glm::dvec3 x = ortho ? glm::dvec3(q / proj.pixelsPerUnit, -z)
                                   : glm::dvec3(q / proj.focalPixels * z, -z);
        bool inside = true;
        double margin = 1e9;
        for (const HalfSpace& h : planes) {
          inside &= h.distance(x) >= 0.0;
          margin = std::min(margin, std::fabs(h.distance(x)));
        }
        if (margin > 1e-9) {
          EXPECT_EQ(inside, !kept.empty() && z >= kept.near && z <= kept.far)
              << (ortho ? "ortho " : "persp ") << pixel.x << "," << pixel.y << " z " << z;
        }
      }
    }
  }
}

TEST(ClipShare, ClippedFractionIsTheSlabShareOfTheKeptPart) {
  const double mu = 5.2, sigma = 0.8;
  const RayInterval all{-kClipUnbounded, kClipUnbounded};
  // Unclipped: the slab split as it was.
  EXPECT_NEAR(clippedSlabFraction(mu, sigma, 4.0, 6.0, false, false, all),
              slabFraction(mu, sigma, 4.0, 6.0), 1e-15);
  EXPECT_NEAR(clippedSlabFraction(mu, sigma, 4.0, 6.0, true, true, all), 1.0, 1e-15);
  // A cut at 5.5: slab [4, 6] keeps [4, 5.5], the open-tailed kernel everything below 5.5.
  const RayInterval below{-kClipUnbounded, 5.5};
  EXPECT_NEAR(clippedSlabFraction(mu, sigma, 4.0, 6.0, false, false, below),
              slabFraction(mu, sigma, 4.0, 5.5), 1e-12);
  EXPECT_NEAR(clippedSlabFraction(mu, sigma, 4.0, 6.0, true, true, below),
              0.5 * (1.0 + std::erf((5.5 - mu) / (std::sqrt(2.0) * sigma))), 2e-7);
  // Slabs of a kernel still add up to its kept share.
  const RayInterval window{4.9, 5.7};
  double sum = clippedSlabFraction(mu, sigma, 0.0, 5.0, true, false, window) +
               clippedSlabFraction(mu, sigma, 5.0, 5.25, false, false, window) +
               clippedSlabFraction(mu, sigma, 5.25, 0.0, false, true, window);
  EXPECT_NEAR(sum, slabFraction(mu, sigma, 4.9, 5.7), 1e-12);
  EXPECT_EQ(clippedSlabFraction(mu, sigma, 0, 0, true, true, RayInterval{3.0, 2.0}), 0.0);
  EXPECT_EQ(clippedSlabFraction(mu, sigma, 6.0, 7.0, false, false, below), 0.0);
}

TEST(ClipShare, CullsOnlyKernelsWhollyOutside) {
  const std::vector<HalfSpace> planes = {{glm::dvec3(0, 0, 1), 3.0}};  // z >= -3
  EXPECT_FALSE(clipCullsKernel(planes, {0, 0, -3.5}, 1.0));
  EXPECT_TRUE(clipCullsKernel(planes, {0, 0, -4.5}, 1.0));
  EXPECT_FALSE(clipCullsKernel({}, {0, 0, -100}, 1.0));
}

// A box's corner cut off by an oblique plane, and a turned box inside it: the bounds are the
// corners left and where the planes cross the box's edges, found from the planes alone; random
// cuts bound every kept point, and a cut keeping nothing leaves nothing.
TEST(ClipShare, PolytopeBoundsAreTheKeptCorners) {
  const DataBox box{glm::dvec3(0.0), glm::dvec3(10.0, 20.0, 30.0)};
  // x + y <= 5 (normal (-1, -1, 0), not of unit length): a prism over the triangle x, y >= 0.
  const auto corner = polytopeBounds(box, {{glm::dvec3(-1, -1, 0), 5.0}});
  ASSERT_TRUE(corner.has_value());
  EXPECT_NEAR(glm::length(corner->low - glm::dvec3(0.0)), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(corner->high - glm::dvec3(5.0, 5.0, 30.0)), 0.0, 1e-9);
  EXPECT_FALSE(polytopeBounds(box, {{glm::dvec3(1, 0, 0), -11.0}}).has_value());  // x >= 11
  const auto whole = polytopeBounds(box, {});
  ASSERT_TRUE(whole.has_value());
  EXPECT_NEAR(glm::length(whole->high - box.high), 0.0, 1e-9);
  // A cube of side 4 about (5, 10, 15), turned: the bounds of its eight corners.
  const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, -1))));
  const glm::dvec3 centre(5.0, 10.0, 15.0);
  std::vector<HalfSpace> faces;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int a = 0; a < 3; ++a)
    for (double side : {-1.0, 1.0}) {
      const glm::dvec3 n = -side * turn[a];  // pointing inwards
      faces.push_back({n, -glm::dot(n, centre + 2.0 * side * turn[a])});
    }
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p =
        centre + 2.0 * ((c & 1 ? 1.0 : -1.0) * turn[0] + (c & 2 ? 1.0 : -1.0) * turn[1] +
                        (c & 4 ? 1.0 : -1.0) * turn[2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const auto turned = polytopeBounds(box, faces);
  ASSERT_TRUE(turned.has_value());
  EXPECT_NEAR(glm::length(turned->low - lo), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(turned->high - hi), 0.0, 1e-9);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<HalfSpace> cuts;
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3 n(u(rng), u(rng), u(rng));
      const glm::dvec3 through(5 + 4 * u(rng), 10 + 9 * u(rng), 15 + 14 * u(rng));
      cuts.push_back({n, -glm::dot(n, through)});
    }
    const auto b = polytopeBounds(box, cuts);
    for (int k = 0; k < 4096; ++k) {  // every kept point of a grid lies within the bounds
      const glm::dvec3 p((k % 16) * 10.0 / 15, (k / 16 % 16) * 20.0 / 15, (k / 256) * 30.0 / 15);
      bool kept = true;
      for (const HalfSpace& h : cuts) kept = kept && h.distance(p) >= 0.0;
      if (!kept) continue;
      ASSERT_TRUE(b.has_value()) << "trial " << trial;
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(b->low[a], p[a] + 1e-9) << "trial " << trial;
        EXPECT_GE(b->high[a], p[a] - 1e-9) << "trial " << trial;
      }
    }
  }
}

// The kept box of a crop, its faces moved out (termination's margin for coarser slab images):
// the crop box grown by that much, but never beyond the volume's grown box.
TEST(ClipShare, KeptBoxMovesTheCutsOutward) {
  const Volume v = makeSyntheticVolume("sphere:16").volume;  // corners 0 and 15
  ClipRegion r;
  r.cropEnabled = true;
  r.cropMin = {4.0, 5.0, 6.0};
  r.cropMax = {9.0, 14.5, 12.0};
  const DataBox tight = keptBoxInVolumeFrame(r, v, 2.0);
  const DataBox moved = keptBoxInVolumeFrame(r, v, 2.0, 1.0);
  const double hair = 1e-3;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(tight.low[a], r.cropMin[a] - hair, 1e-9);
    EXPECT_NEAR(moved.low[a], r.cropMin[a] - 1.0 - hair, 1e-9);
  }
  EXPECT_NEAR(moved.high.x, 10.0 + hair, 1e-9);
  EXPECT_NEAR(moved.high.y, 15.5 + hair, 1e-9);
  EXPECT_NEAR(moved.high.z, 13.0 + hair, 1e-9);
  // Moved past the volume's box grown by 2 (15 + 2): held there.
  const DataBox far = keptBoxInVolumeFrame(r, v, 2.0, 5.0);
  EXPECT_NEAR(far.high.y, 17.0, 1e-9);
}

TEST(ClipShare, VolumeFrameUndoesTheDirection) {
  Volume v = makeSyntheticVolume("sphere:8").volume;
  const glm::dmat3 d(glm::rotate(glm::dmat4(1.0), 0.6, glm::normalize(glm::dvec3(1, -2, 1))));
  v.setDirection(d, false);
  ClipRegion r;
  r.planes.push_back({glm::dvec3(2, 3, 1), glm::normalize(glm::dvec3(1, 1, -0.5)), true});
  const std::vector<HalfSpace> frame = halfSpacesInVolumeFrame(r, v);
  ASSERT_EQ(frame.size(), 1u);
  const glm::dvec3 o = v.origin();
  for (const glm::dvec3 ijk : {glm::dvec3(0), glm::dvec3(3, 1, 7), glm::dvec3(7, 7, 2)}) {
    const glm::dvec3 local = o + ijk * v.spacing();
    const glm::dvec3 world = o + d * (local - o);
    EXPECT_NEAR(frame[0].distance(local), r.halfSpaces()[0].distance(world), 1e-12);
  }
}

// Every cell of every slice row: kept exactly when its sample position, back in world space,
// is inside the region.
TEST(ShearWarpClip, KeptCellsAreTheSamplesInside) {
  Volume v = makeSyntheticVolume("sphere:16").volume;
  v.setDirection(glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 0, 1))), false);
  ClipRegion r;
  r.cropEnabled = true;
  r.cropMin = {2.3, -5.0, 3.1};
  r.cropMax = {11.7, 12.2, 14.0};
  r.planes.push_back({glm::dvec3(8, 8, 8), glm::normalize(glm::dvec3(0.4, -1, 0.3)), true});
  Camera cam;
  cam.focalPoint = {8, 8, 8};
  cam.position = {30, 14, 20};
  const ShearWarpFactorization view = factorizeView(cam, v.dims(), v.spacing(), v.origin(), 64, 64);
  const ShearWarpClip clip(r, v, view);
  ASSERT_TRUE(clip.active());
  size_t kept = 0, total = 0;
  for (int k = 0; k < view.depth; ++k) {
    const double fi = 0.37, fj = 0.61;  // as a slice's bilinear fractions would be
    for (int j = 0; j + 1 < view.height; ++j) {
      int first = 0, last = view.width - 1;
      clip.keptCells(k, j, fi, fj, &first, &last);
      for (int i = 0; i + 1 < view.width; ++i) {
        glm::dvec3 ijk;
        ijk[view.axisI] = i + fi;
        ijk[view.axisJ] = j + fj;
        ijk[view.principal] = k;
        const glm::dvec3 local = v.origin() + ijk * v.spacing();
        const glm::dvec3 world = v.origin() + v.direction() * (local - v.origin());
        const bool in = i >= first && i < last;
        EXPECT_EQ(in, r.contains(world)) << k << " " << j << " " << i;
        kept += in;
        ++total;
      }
    }
  }
  EXPECT_GT(kept, total / 10);
  EXPECT_LT(kept, total * 9 / 10);
}

// The shear-warp picture of a cropped volume: nothing where the box is cut away, the same
// picture where whole rays stay inside it.
TEST(ShearWarpClip, CropKeepsOnlyTheBoxInThePicture) {
  const Volume v = makeSyntheticVolume("sphere:32").volume;
  TransferFunction tf;
  tf.opacity = {{v.minValue(), 0.0}, {v.maxValue(), 0.5}};
  tf.color = {{v.minValue(), glm::dvec3(1.0)}, {v.maxValue(), glm::dvec3(1.0)}};
  ShearWarp sw;
  sw.setVolume(v);
  sw.setTransferFunction(tf);
  Camera cam;
  const glm::dvec3 c = 0.5 * (v.boundsMin() + v.boundsMax());
  cam.focalPoint = c;
  cam.position = c + glm::dvec3(0, 0, 100);
  cam.orthographic = true;
  ShearWarpSettings s;
  s.threads = 1;
  sw.render(cam, s, 64, 64);
  const FloatImage full = sw.image();
  ClipRegion r;
  r.cropEnabled = true;
  r.cropMin = glm::dvec3(-100.0);
  r.cropMax = glm::dvec3(c.x, 100.0, 100.0);  // the half with x <= centre
  sw.render(cam, s, 64, 64, r);
  const FloatImage half = sw.image();
  double leftFull = 0, leftHalf = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      if (x >= 34) {
        EXPECT_EQ(half.at(x, y, 3), 0.0f) << x << "," << y;  // cut away
      }
      if (x < 30) {
        EXPECT_NEAR(half.at(x, y, 3), full.at(x, y, 3), 1e-6) << x << "," << y;
        leftFull += full.at(x, y, 3);
        leftHalf += half.at(x, y, 3);
      }
    }
  EXPECT_GT(leftFull, 10.0);
  // A box holding nothing of the volume leaves nothing.
  r.cropMin = glm::dvec3(500.0);
  r.cropMax = glm::dvec3(600.0);
  sw.render(cam, s, 64, 64, r);
  double sum = 0;
  for (float p : sw.image().values) sum += p;
  EXPECT_EQ(sum, 0.0);
}

}  // namespace
}  // namespace ewa
