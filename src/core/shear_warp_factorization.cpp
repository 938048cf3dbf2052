// Shear-warp factorization: principal axis, shear per slice, intermediate image size, warp.
#include "core/shear_warp_factorization.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace ewa {

ShearWarpFactorization factorizeView(const Camera& camera, const std::array<int64_t, 3>& dims,
                                     const glm::dvec3& spacing, const glm::dvec3& origin, int width,
                                     int height) {
  ShearWarpFactorization f;
  f.perspectiveAsParallel = !camera.orthographic;
  const glm::dvec3 dir = camera.direction();
  // The ray in voxel units: the principal axis is where it advances fastest.
  const glm::dvec3 step = dir / spacing;
  int p = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(step[c]) > std::abs(step[p])) p = c;
  f.principal = p;
  f.axisI = (p + 1) % 3;
  f.axisJ = (p + 2) % 3;
  f.width = int(dims[f.axisI]);
  f.height = int(dims[f.axisJ]);
  f.depth = int(dims[p]);
  f.increasing = step[p] > 0.0;
  const double ri = step[f.axisI] / step[p];
  const double rj = step[f.axisJ] / step[p];
  // Voxel (i, j, k) lies on the ray through (i - k ri, j - k rj) of slice 0; shift so that
  // every offset is >= 0.
  const double last = std::max(0, f.depth - 1);
  f.shearI = -ri;
  f.shearJ = -rj;
  f.translateI = std::max(0.0, last * ri);
  f.translateJ = std::max(0.0, last * rj);
  const double maxI = std::ceil(std::max(f.offsetI(0), f.offsetI(f.depth - 1)));
  const double maxJ = std::ceil(std::max(f.offsetJ(0), f.offsetJ(f.depth - 1)));
  f.imageWidth = std::max(1, int(maxI) + std::max(1, f.width - 1));
  f.imageHeight = std::max(1, int(maxJ) + std::max(1, f.height - 1));
  f.sliceSpacing = spacing[p];
  f.sampleRatio = 1.0 / std::abs(dir[p]);

  // Warp: intermediate (u, v) is voxel (u - tI, v - tJ) of slice 0; project it like the splat
  // renderer does (orthographic, pixels per unit at the focal point).
  const Projection proj = camera.projection(width, height);
  const glm::dmat4 view = camera.viewMatrix();
  auto toPixel = [&](const glm::dvec3& world) {
    const glm::dvec3 q(view * glm::dvec4(world, 1.0));
    return proj.principal + glm::dvec2(q.x, q.y) * proj.pixelsPerUnit;
  };
  glm::dvec3 idx0(0.0);
  idx0[f.axisI] = -f.translateI;
  idx0[f.axisJ] = -f.translateJ;
  glm::dvec3 du(0.0), dv(0.0);
  du[f.axisI] = 1.0;
  dv[f.axisJ] = 1.0;
  const glm::dvec2 p0 = toPixel(origin + idx0 * spacing);
  const glm::dvec2 pu = toPixel(origin + (idx0 + du) * spacing) - p0;
  const glm::dvec2 pv = toPixel(origin + (idx0 + dv) * spacing) - p0;
  f.warp = glm::dmat3(glm::dvec3(pu, 0.0), glm::dvec3(pv, 0.0), glm::dvec3(p0, 1.0));
  const double det = pu.x * pv.y - pu.y * pv.x;
  f.inverseWarp = std::abs(det) > 1e-300 ? glm::inverse(f.warp) : glm::dmat3(0.0);
  return f;
}

}  // namespace ewa
