// Shear-warp factorization: principal axis, per-slice shear (and scale), intermediate image, warp.
#include "core/shear_warp_factorization.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace ewa {

namespace {

// The principal axis, in-slice axes, sizes and spacing of a view whose rays advance by `step`
// (voxel units) along the principal axis fastest.
void chooseAxes(const glm::dvec3& step, const std::array<int64_t, 3>& dims,
                const glm::dvec3& spacing, ShearWarpFactorization& f) {
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
  f.spacing = glm::dvec3(spacing[f.axisI], spacing[f.axisJ], spacing[p]);
  f.sliceSpacing = spacing[p];
}

// Slice coordinates (i, j, k) of a world point, and the world offset of a slice-space vector.
glm::dvec3 toSlice(const ShearWarpFactorization& f, const glm::dvec3& world,
                   const glm::dvec3& origin, const glm::dvec3& spacing) {
  const glm::dvec3 idx = (world - origin) / spacing;
  return {idx[f.axisI], idx[f.axisJ], idx[f.principal]};
}

glm::dvec3 toIndex(const ShearWarpFactorization& f, const glm::dvec3& slice) {
  glm::dvec3 idx(0.0);
  idx[f.axisI] = slice.x;
  idx[f.axisJ] = slice.y;
  idx[f.principal] = slice.z;
  return idx;
}

void setInverse(ShearWarpFactorization& f) {
  const double det = glm::determinant(f.warp);
  f.inverseWarp = std::abs(det) > 1e-300 ? glm::inverse(f.warp) : glm::dmat3(0.0);
}

// Narrows a parallel view's intermediate image to the picture's rays (its corners', two pixels
// wider), by whole pixels so that every slice keeps its bilinear weights: a close-up composites
// what it shows, not the whole volume's shadow.
void cropToPicture(int width, int height, ShearWarpFactorization& f) {
  if (std::abs(glm::determinant(f.warp)) <= 1e-300) return;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (double x : {0.0, double(width)})
    for (double y : {0.0, double(height)}) {
      const glm::dvec3 uv = f.inverseWarp * glm::dvec3(x, y, 1.0);
      for (int axis = 0; axis < 2; ++axis) {
        lo[axis] = std::min(lo[axis], uv[axis]);
        hi[axis] = std::max(hi[axis], uv[axis]);
      }
    }
  const double size[2] = {double(f.imageWidth), double(f.imageHeight)};
  int first[2], end[2];
  for (int axis = 0; axis < 2; ++axis) {
    first[axis] = int(std::clamp(std::floor(lo[axis]) - 2.0, 0.0, size[axis]));
    end[axis] = int(std::clamp(std::ceil(hi[axis]) + 2.0, 0.0, size[axis]));
  }
  if (first[0] >= end[0] || first[1] >= end[1]) {  // the volume lies outside the picture
    f.sliceCount = 0;
    f.imageWidth = f.imageHeight = 1;
    return;
  }
  f.translateI -= first[0];
  f.translateJ -= first[1];
  f.imageWidth = end[0] - first[0];
  f.imageHeight = end[1] - first[1];
  // Intermediate pixel u now is u + first of the uncropped image.
  f.warp = f.warp * glm::dmat3(glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0),
                               glm::dvec3(first[0], first[1], 1.0));
  setInverse(f);
}

void factorizeParallel(const Camera& camera, const std::array<int64_t, 3>& dims,
                       const glm::dvec3& spacing, const glm::dvec3& origin, int width, int height,
                       double maxPerVoxel, ShearWarpFactorization& f) {
  const glm::dvec3 dir = camera.direction();
  chooseAxes(dir / spacing, dims, spacing, f);
  const glm::dvec3 step = dir / spacing;
  const int p = f.principal;
  f.frontSlice = f.increasing ? 0 : f.depth - 1;
  f.sliceCount = f.depth;
  const Projection proj = camera.projection(width, height);
  // m intermediate pixels a voxel: the picture's pixels across the wider voxel side (so that
  // both axes are at least as fine as the picture), from 1 up to maxPerVoxel.
  const double across = std::max(spacing[f.axisI], spacing[f.axisJ]);
  const double m = std::clamp(proj.pixelsPerUnit * across, 1.0, std::max(1.0, maxPerVoxel));
  f.magnification = m;
  const double ri = step[f.axisI] / step[p];
  const double rj = step[f.axisJ] / step[p];
  // Voxel (i, j, k) lies on the ray through (i - k ri, j - k rj) of slice 0, intermediate
  // pixel m (i - k ri, j - k rj); shift so that every offset is >= 0.
  const double last = std::max(0, f.depth - 1);
  f.shearI = -m * ri;
  f.shearJ = -m * rj;
  f.translateI = std::max(0.0, m * last * ri);
  f.translateJ = std::max(0.0, m * last * rj);
  const double maxI = std::ceil(std::max(f.offsetI(0), f.offsetI(f.depth - 1)));
  const double maxJ = std::ceil(std::max(f.offsetJ(0), f.offsetJ(f.depth - 1)));
  // A magnified slice's last column lands on pixel ceil(m (width - 1)) + offset: one more.
  const int edge = m > 1.0 ? 1 : 0;
  f.imageWidth = std::max(1, int(maxI) + std::max(1, int(std::ceil(m * (f.width - 1)))) + edge);
  f.imageHeight = std::max(1, int(maxJ) + std::max(1, int(std::ceil(m * (f.height - 1)))) + edge);
  f.sampleRatio = 1.0 / std::abs(dir[p]);

  // Warp: intermediate (u, v) is voxel ((u - tI) / m, (v - tJ) / m) of slice 0; project it
  // like the splat renderer does (orthographic, pixels per unit at the focal point).
  const glm::dmat4 view = camera.viewMatrix();
  auto toPixel = [&](const glm::dvec3& world) {
    const glm::dvec3 q(view * glm::dvec4(world, 1.0));
    return proj.principal + glm::dvec2(q.x, q.y) * proj.pixelsPerUnit;
  };
  const glm::dvec3 idx0 = toIndex(f, {-f.translateI / m, -f.translateJ / m, 0.0});
  const glm::dvec2 p0 = toPixel(origin + idx0 * spacing);
  const glm::dvec2 pu = toPixel(origin + (idx0 + toIndex(f, {1.0 / m, 0, 0})) * spacing) - p0;
  const glm::dvec2 pv = toPixel(origin + (idx0 + toIndex(f, {0, 1.0 / m, 0})) * spacing) - p0;
  f.warp = glm::dmat3(glm::dvec3(pu, 0.0), glm::dvec3(pv, 0.0), glm::dvec3(p0, 1.0));
  setInverse(f);
  cropToPicture(width, height, f);
}

// False when the intermediate image would be too large (the caller draws the parallel view).
bool factorizePerspective(const Camera& camera, const std::array<int64_t, 3>& dims,
                          const glm::dvec3& spacing, const glm::dvec3& origin, int width,
                          int height, double maxPerVoxel, ShearWarpFactorization& f) {
  const glm::dvec3 dir = camera.direction();
  chooseAxes(dir / spacing, dims, spacing, f);
  f.perspective = true;
  f.eye = toSlice(f, camera.position, origin, spacing);
  f.sampleRatio = 1.0 / std::abs(dir[f.principal]);  // the view axis' ray (statistics)
  // The slices drawn: at least one voxel in front of the eye, front to back.
  const double ahead = f.increasing ? 1.0 : -1.0;
  const double nearest = f.eye.z + ahead;  // the near plane
  const int first = f.increasing ? std::max(0, int(std::ceil(nearest)))
                                 : std::min(f.depth - 1, int(std::floor(nearest)));
  const int last = f.increasing ? f.depth - 1 : 0;
  f.frontSlice = first;
  f.sliceCount = std::max(0, int(ahead) * (last - first) + 1);
  if (first < 0 || first >= f.depth) f.sliceCount = 0;
  f.imageWidth = f.imageHeight = 1;
  f.warp = glm::dmat3(1.0);
  f.inverseWarp = glm::dmat3(0.0);     // reads nothing
  if (f.sliceCount == 0) return true;  // nothing in front of the eye: an empty picture

  // Pixel (x, y, 1) -> the ray's direction in slice coordinates, A (x, y, 1).
  const Projection proj = camera.projection(width, height);
  const glm::dmat3 toCamera(glm::dvec3(1.0 / proj.focalPixels, 0.0, 0.0),
                            glm::dvec3(0.0, 1.0 / proj.focalPixels, 0.0),
                            glm::dvec3(-proj.principal / proj.focalPixels, -1.0));
  const glm::dmat3 toWorld = glm::transpose(camera.rotation());
  glm::dmat3 toSliceDir(0.0);  // world direction -> slice-coordinate direction
  toSliceDir[f.axisI][0] = 1.0 / spacing[f.axisI];
  toSliceDir[f.axisJ][1] = 1.0 / spacing[f.axisJ];
  toSliceDir[f.principal][2] = 1.0 / spacing[f.principal];
  const glm::dmat3 a = toSliceDir * toWorld * toCamera;
  // A ray d meets slice k at eye + (k - eye.z) d / d.z; its intermediate pixel is
  // (c ahead d.x / d.z + tI, c ahead d.y / d.z + tJ) for every slice, with scale(k) = c /
  // |k - eye.z|. c: the picture's pixels per voxel along the view axis (a voxel across at
  // distance t is focal / t pixels; t = |k - eye.z| spacing_p / |dir_p|; by the wider voxel
  // side, so that both axes are at least as fine as the picture), but no more than
  // maxPerVoxel intermediate pixels a voxel on the focal point's slice (the warp
  // magnifies the rest; kMaxIntermediatePerVoxel by default), and at least one a voxel on the
  // front slice, as Lacroute's.
  const double across = std::max(spacing[f.axisI], spacing[f.axisJ]);
  const double picture = proj.focalPixels * std::abs(dir[f.principal]) * across / f.sliceSpacing;
  const double focal = std::abs(toSlice(f, camera.focalPoint, origin, spacing).z - f.eye.z);
  const double c = std::max(std::min(picture, std::max(1.0, maxPerVoxel) * std::max(focal, 1.0)),
                            std::abs(first - f.eye.z));
  f.referenceDistance = c;
  // The intermediate image: where the slices' projections and the picture's rays meet.
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  const double extent[2] = {double(std::max(0, f.width - 1)), double(std::max(0, f.height - 1))};
  const double eye[2] = {f.eye.x, f.eye.y};
  for (int k : {first, last}) {
    const double s = c / std::abs(k - f.eye.z);
    for (int axis = 0; axis < 2; ++axis)
      for (double x : {0.0, extent[axis]}) {
        lo[axis] = std::min(lo[axis], s * (x - eye[axis]));
        hi[axis] = std::max(hi[axis], s * (x - eye[axis]));
      }
  }
  double rayLo[2] = {1e300, 1e300}, rayHi[2] = {-1e300, -1e300};
  bool frustum = true;  // every corner ray runs away from the eye along the principal axis
  for (double x : {0.0, double(width)})
    for (double y : {0.0, double(height)}) {
      const glm::dvec3 d = a * glm::dvec3(x, y, 1.0);
      if (!(ahead * d.z > 1e-9 * glm::length(d))) frustum = false;
      for (int axis = 0; axis < 2; ++axis) {
        const double at = c * ahead * d[axis] / d.z;
        rayLo[axis] = std::min(rayLo[axis], at);
        rayHi[axis] = std::max(rayHi[axis], at);
      }
    }
  if (frustum)
    for (int axis = 0; axis < 2; ++axis) {
      lo[axis] = std::max(lo[axis], rayLo[axis] - 2.0);
      hi[axis] = std::min(hi[axis], rayHi[axis] + 2.0);
    }
  if (!(lo[0] <= hi[0] && lo[1] <= hi[1])) {  // the volume lies outside the view
    f.sliceCount = 0;
    return true;
  }
  const double w = std::ceil(hi[0]) - std::floor(lo[0]) + 2.0;
  const double h = std::ceil(hi[1]) - std::floor(lo[1]) + 2.0;
  if (!(w * h <= kMaxPerspectiveIntermediatePixels)) return false;
  f.imageWidth = int(w);
  f.imageHeight = int(h);
  // scale(k) (x - eye.x) + tI = scale(k) x + offsetI(k): tI - c eye.x / |k - eye.z| is offsetI.
  f.translateI = -std::floor(lo[0]);
  f.translateJ = -std::floor(lo[1]);
  // Inverse warp: pixel -> (c d.x + tI w, c d.y + tJ w, w) with w = ahead d.z.
  const glm::dvec3 rowX(a[0][0], a[1][0], a[2][0]), rowY(a[0][1], a[1][1], a[2][1]),
      rowZ(a[0][2], a[1][2], a[2][2]);
  const glm::dvec3 wRow = ahead * rowZ;
  const glm::dvec3 uRow = c * rowX + f.translateI * wRow, vRow = c * rowY + f.translateJ * wRow;
  f.inverseWarp = glm::transpose(glm::dmat3(uRow, vRow, wRow));
  const double det = glm::determinant(f.inverseWarp);
  f.warp = std::abs(det) > 1e-300 ? glm::inverse(f.inverseWarp) : glm::dmat3(1.0);
  return true;
}

}  // namespace

double ShearWarpFactorization::rayRatio(double u, double v) const {
  if (!perspective) return sampleRatio;
  // The ray through (u, v) advances (u - tI, v - tJ) / c voxels across per voxel along the
  // principal axis: its world length per slice over the slice spacing.
  const glm::dvec3 d((u - translateI) / referenceDistance * spacing.x,
                     (v - translateJ) / referenceDistance * spacing.y, spacing.z);
  return glm::length(d) / spacing.z;
}

ShearWarpFactorization factorizeView(const Camera& camera, const std::array<int64_t, 3>& dims,
                                     const glm::dvec3& spacing, const glm::dvec3& origin, int width,
                                     int height, double maxPerVoxel) {
  ShearWarpFactorization f;
  if (!camera.orthographic &&
      factorizePerspective(camera, dims, spacing, origin, width, height, maxPerVoxel, f))
    return f;
  f = ShearWarpFactorization{};
  f.perspectiveAsParallel = !camera.orthographic;
  factorizeParallel(camera, dims, spacing, origin, width, height, maxPerVoxel, f);
  return f;
}

}  // namespace ewa
