// Surface splats (EWA paper, section 5) on the GPU: the flat footprint equals the C++ one, a
// sphere's silhouette is the analytic circle, its shading follows the analytic normal.
#include <cmath>
#include <glm/geometric.hpp>

#include "render_fixture.h"

namespace ewa::test {
namespace {

class SurfaceSplats : public RenderFixture {};

// Transparent everywhere: only the surface splats are drawn, white.
TransferFunction clearTf() {
  TransferFunction tf;
  tf.opacity = {{-10.0, 0.0}, {10.0, 0.0}};
  return tf;
}

RenderSettings surfaceSettings(double threshold) {
  RenderSettings s = paperSettings();
  s.classification.surface = SurfaceCriterion::Value;
  s.classification.threshold = threshold;
  s.surfaceOpacity = 0.999;
  return s;
}

TEST_F(SurfaceSplats, ShaderFootprintEqualsCppReference) {
  // One voxel above the threshold with unequal neighbours: an oblique normal and an offset.
  const Volume vol = floatVolume(5, [](int i, int j, int k) {
    if (i == 2 && j == 2 && k == 2) return 1.0f;
    if (j == 2 && k == 2 && i == 1) return 0.5f;
    if (i == 2 && k == 2 && j == 1) return 0.25f;
    if (i == 2 && j == 2 && k == 1) return 0.6f;
    return 0.0f;
  });
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(clearTf());
  for (FilterMode filter : {FilterMode::Ewa, FilterMode::Plain}) {
    Camera cam;
    cam.focalPoint = {2.2, 1.9, 2.0};
    cam.position = cam.focalPoint + glm::dvec3(2.0, -3.0, 5.0);
    RenderSettings settings = surfaceSettings(0.8);
    settings.filter = filter;
    settings.mode = RenderMode::XRay;
    const int w = 96, h = 80;
    renderer()->render(cam, settings, w, h);
    ASSERT_EQ(renderer()->stats().surfaceSplats, 1u);
    const std::vector<float> depth = renderer()->readOpticalDepth();
    // The same splat in C++, from the packed attributes the GPU read.
    const UnpackedAttributes a = unpackAttributes(renderer()->attributes().at(0));
    ASSERT_TRUE(a.surface);
    EXPECT_GT(std::abs(a.normal.x), 0.2);
    const glm::dvec3 world = vol.worldPosition(2, 2, 2) + a.normal * a.offset;
    const glm::dvec3 u(cam.viewMatrix() * glm::dvec4(world, 1.0));
    FootprintParams params;
    params.filter = filter;
    const Footprint fp =
        computeFootprint(u, surfaceCovariance(cam.rotation(), vol.spacing(), a.normal),
                         cam.projection(w, h), params);
    ASSERT_TRUE(fp.visible);
    const double g = surfaceSplatMass(vol.spacing(), a.normal, -std::log(1.0 - 0.999));
    double peak = 0.0, worst = 0.0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double expected = g * footprintWeight(fp, {x + 0.5, y + 0.5}, params.cutoff);
        peak = std::max(peak, expected);
        worst = std::max(worst, std::abs(depth[size_t(y) * w + x] - expected));
      }
    EXPECT_GT(peak, 0.0);
    EXPECT_LT(worst, 3e-3 * peak) << filterModeName(filter);
  }
}

TEST_F(SurfaceSplats, SphereSilhouetteAndShadingMatchTheAnalyticSphere) {
  const int n = 32;
  const double c = 15.5, radius = 10.0;
  // A linear ramp across the surface, 0.5 at the radius: exact crossings and normals.
  const Volume vol = floatVolume(n, [&](int i, int j, int k) {
    const double r = glm::length(glm::dvec3(i, j, k) - glm::dvec3(c));
    return float(std::clamp(0.5 - (r - radius) / 3.0, 0.0, 1.0));
  });
  renderer()->setVolume(vol);
  renderer()->setTransferFunction(clearTf());
  Camera cam;
  cam.focalPoint = glm::dvec3(c);
  cam.position = cam.focalPoint + glm::dvec3(0.0, 0.0, 40.0);
  cam.orthographic = true;
  cam.viewAngleDeg = 2.0 * std::atan(0.45) * 180.0 / 3.14159265358979;  // 36 units over 64 px
  const int size = 64;
  const Projection proj = cam.projection(size, size);
  RenderSettings settings = surfaceSettings(0.5);
  // Plain: the geometry of the splats alone. EWA adds its one-pixel low-pass on purpose, and
  // an opaque layer saturates its tails, which moves the half-opacity edge out by about 1.5 px.
  settings.filter = FilterMode::Plain;
  renderer()->render(cam, settings, size, size);
  const Image8 cover = renderer()->readImage();  // white: the pixel value is the opacity
  settings.lighting.enabled = true;
  settings.lighting.ambient = 0.2;
  settings.lighting.diffuse = 0.8;
  settings.lighting.specular = 0.0;
  renderer()->render(cam, settings, size, size);
  const Image8 shaded = renderer()->readImage();
  ASSERT_GT(renderer()->stats().surfaceSplats, 500u);

  const double rPixels = radius * proj.pixelsPerUnit;
  const glm::dvec2 centre = proj.principal;  // rows of the image run top down
  double area = 0.0, worstShade = 0.0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const size_t p = (size_t(y) * size + x) * 3;
      const double alpha = cover.pixels[p] / 255.0;
      area += alpha;
      const glm::dvec2 d(x + 0.5 - centre.x, (size - 1 - y) + 0.5 - centre.y);
      const double rr = glm::length(d) / rPixels;
      if (rr < 0.8) {
        const double nz = std::sqrt(1.0 - rr * rr);
        const double expected = alpha * (0.2 + 0.8 * nz);
        worstShade = std::max(worstShade, std::abs(shaded.pixels[p] / 255.0 - expected));
      }
    }
  // Silhouette: the covered area's equivalent radius, and the half-opacity crossing along rows.
  EXPECT_NEAR(std::sqrt(area / 3.14159265358979), rPixels, 0.5);
  for (int dir = 0; dir < 4; ++dir) {
    const glm::dvec2 step = dir == 0   ? glm::dvec2(1, 0)
                            : dir == 1 ? glm::dvec2(-1, 0)
                            : dir == 2 ? glm::dvec2(0, 1)
                                       : glm::dvec2(0, -1);
    double prev = 1.0, crossing = -1.0;
    for (double t = 0.5; t < 30.0; t += 1.0) {
      const glm::dvec2 q = centre + step * t;  // pixel centres along an axis
      const int x = int(std::floor(q.x)), y = size - 1 - int(std::floor(q.y));
      const double a = cover.pixels[(size_t(y) * size + x) * 3] / 255.0;
      if (a < 0.5 && prev >= 0.5) {
        crossing = t - 1.0 + (prev - 0.5) / (prev - a);
        break;
      }
      prev = a;
    }
    EXPECT_NEAR(crossing, rPixels, 0.5) << "direction " << dir;
  }
  EXPECT_LT(worstShade, 0.03);
}

}  // namespace
}  // namespace ewa::test
