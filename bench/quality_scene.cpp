// Benchmark scenes, per-pixel sheet depth and footprint shape, sub-pixel camera moves.
#include "bench/quality_scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <stdexcept>

#include "core/ewa_footprint.h"

namespace ewa {

namespace {

// True when a pixel within kSilhouetteMargin of (x, y) is off the sheet or off the image.
bool nearSilhouette(const PixelMask& sheet, int width, int height, int x, int y) {
  for (int dy = -kSilhouetteMargin; dy <= kSilhouetteMargin; ++dy)
    for (int dx = -kSilhouetteMargin; dx <= kSilhouetteMargin; ++dx) {
      const int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= width || yy >= height) return true;
      if (!sheet[size_t(yy) * width + xx]) return true;
    }
  return false;
}

}  // namespace

Camera QualityScene::camera() const {
  Camera c;
  c.position = position;
  c.focalPoint = focalPoint;
  c.viewUp = viewUp;
  c.viewAngleDeg = viewAngleDeg;
  return c;
}

std::vector<QualityScene> qualityScenes() {
  // The checkerboard view is the README's and the reference test's; the zebra views look along
  // +y (the coarse axis), so the stripes (along the dense x axis) run towards the horizon and
  // the kernels, thin in x, project to ellipses.
  return {
      {"checkerboard:10",
       "checkerboard 10x10 squares (Swan Fig. 7)",
       {200, -120, 25},
       {200, 400, 0},
       {0, 0, 1},
       30.0},
      {"zebra:2",
       "zebra, 2:1 kernels (Zwicker Fig. 8, top)",
       {128, -40, 12},
       {128, 256, 0},
       {0, 0, 1},
       30.0},
      {"zebra:4",
       "zebra, 4:1 kernels (Zwicker Fig. 8, bottom)",
       {128, -40, 12},
       {128, 256, 0},
       {0, 0, 1},
       30.0},
  };
}

SheetRegions sheetRegions(const Volume& sheet, const Camera& camera, int width, int height) {
  if (sheet.dims()[2] != 1)
    throw std::invalid_argument("sheetRegions: the volume is not a one-voxel-thick sheet");
  SheetRegions r;
  r.width = width;
  r.height = height;
  const size_t n = size_t(width) * height;
  r.depth.assign(n, 0.0f);
  r.aspect.assign(n, 0.0f);
  r.sheet.assign(n, 0);
  r.beyondK.assign(n, 0);
  r.anisotropic.assign(n, 0);
  const Projection proj = camera.projection(width, height);
  const glm::dvec3 sp = sheet.spacing();
  const double s = std::min({sp.x, sp.y, sp.z});
  r.k = s * proj.focalPixels;
  const glm::dmat3 w = camera.rotation();
  const glm::dmat4 view = camera.viewMatrix();
  const glm::dmat3 cov = cameraCovariance(w, sp);
  FootprintParams params;
  params.filter = FilterMode::Plain;
  const glm::dvec3 lo = sheet.origin();
  const glm::dvec3 hi =
      sheet.worldPosition(double(sheet.dims()[0] - 1), double(sheet.dims()[1] - 1), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // Pixel centres in the footprint's coordinates (y up); images are stored top row first.
      const glm::dvec2 pixel(x + 0.5, height - y - 0.5);
      const glm::dvec3 rayCam((pixel.x - proj.principal.x) / proj.focalPixels,
                              (pixel.y - proj.principal.y) / proj.focalPixels, -1.0);
      const glm::dvec3 rayWorld = glm::transpose(w) * rayCam;  // W is orthonormal
      if (std::abs(rayWorld.z) < 1e-12) continue;
      const double t = (lo.z - camera.position.z) / rayWorld.z;  // depth: rayCam.z is -1
      if (!(t > 0.0)) continue;
      const glm::dvec3 hit = camera.position + t * rayWorld;
      if (hit.x < lo.x || hit.x > hi.x || hit.y < lo.y || hit.y > hi.y) continue;
      const size_t p = size_t(y) * width + x;
      r.sheet[p] = 1;
      r.depth[p] = float(t);
      const Footprint fp =
          computeFootprint(glm::dvec3(view * glm::dvec4(hit, 1.0)), cov, proj, params);
      const glm::dmat2& c = fp.covariance;
      const double mean = 0.5 * (c[0][0] + c[1][1]);
      const double disc =
          std::sqrt(0.25 * (c[0][0] - c[1][1]) * (c[0][0] - c[1][1]) + c[0][1] * c[0][1]);
      const double minor = std::max(mean - disc, 1e-30), major = mean + disc;
      r.aspect[p] = float(std::sqrt(major / minor));
    }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = size_t(y) * width + x;
      if (!r.sheet[p] || !(r.depth[p] > r.k) || nearSilhouette(r.sheet, width, height, x, y))
        continue;
      r.beyondK[p] = 1;
      r.anisotropic[p] = r.aspect[p] >= kAnisotropicAspect;
    }
  return r;
}

Camera shiftedCamera(const Camera& camera, int width, int height, double dx, double dy) {
  const Projection proj = camera.projection(width, height);
  const glm::dmat3 w = camera.rotation();
  // Rows of W are the camera's right, up and backward axes in world space.
  const glm::dvec3 right(w[0][0], w[1][0], w[2][0]);
  const glm::dvec3 up(w[0][1], w[1][1], w[2][1]);
  const glm::dvec3 dir = camera.direction();
  Camera out = camera;
  const glm::dvec3 turned =
      glm::normalize(dir + right * (dx / proj.focalPixels) + up * (dy / proj.focalPixels));
  out.focalPoint = camera.position + turned * camera.distance();
  return out;
}

}  // namespace ewa
