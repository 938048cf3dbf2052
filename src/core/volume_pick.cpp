// Picking along a pixel's ray: a small CPU ray march through the trilinear field.
#include "core/volume_pick.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>

namespace ewa {

namespace {

// The most samples one ray takes: a ray through 65536 voxels at four samples each; longer
// ones (a huge, thin spacing) take longer steps instead of hanging the window.
constexpr double kMaxSteps = 4.0 * 65536.0;

// The part of index-space ray oi + t di inside the box [low, high] (slab test), within `span`.
void clipToBox(const DataBox& box, const glm::dvec3& oi, const glm::dvec3& di, RayInterval* span) {
  for (int a = 0; a < 3; ++a) {
    if (di[a] == 0.0) {
      if (oi[a] < box.low[a] || oi[a] > box.high[a]) *span = RayInterval{1.0, 0.0};
      continue;
    }
    double t0 = (box.low[a] - oi[a]) / di[a], t1 = (box.high[a] - oi[a]) / di[a];
    if (t0 > t1) std::swap(t0, t1);
    span->near = std::max(span->near, t0);
    span->far = std::min(span->far, t1);
  }
}

}  // namespace

PickRay pickRay(const Camera& camera, int width, int height, const glm::dvec2& point) {
  const Projection proj = camera.projection(std::max(width, 1), std::max(height, 1));
  const glm::dmat3 toWorld = glm::transpose(camera.rotation());
  // Pixel coordinates have y up (as the renderers' principal point does).
  const glm::dvec2 q(point.x - proj.principal.x, (proj.height - point.y) - proj.principal.y);
  PickRay ray;
  if (proj.orthographic) {
    ray.origin = camera.position + toWorld * glm::dvec3(q / proj.pixelsPerUnit, 0.0);
    ray.direction = glm::normalize(toWorld * glm::dvec3(0.0, 0.0, -1.0));
  } else {
    ray.origin = camera.position;
    ray.direction = glm::normalize(toWorld * glm::dvec3(q / proj.focalPixels, -1.0));
  }
  return ray;
}

std::optional<glm::dvec2> windowPoint(const Camera& camera, int width, int height,
                                      const glm::dvec3& p) {
  const Projection proj = camera.projection(std::max(width, 1), std::max(height, 1));
  const glm::dvec3 c = glm::dvec3(camera.viewMatrix() * glm::dvec4(p, 1.0));
  if (!proj.orthographic && !(-c.z > 1e-9)) return std::nullopt;  // at or behind the eye
  const glm::dvec2 lateral = proj.orthographic ? glm::dvec2(c) * proj.pixelsPerUnit
                                               : glm::dvec2(c) / -c.z * proj.focalPixels;
  return glm::dvec2(proj.principal.x + lateral.x, proj.height - (proj.principal.y + lateral.y));
}

double trilinearValue(const Volume& volume, const glm::dvec3& index) {
  const auto& d = volume.dims();
  int64_t lo[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double top = double(std::max<int64_t>(d[a], 1) - 1);
    const double x = std::clamp(index[a], 0.0, top);
    lo[a] = std::min<int64_t>(int64_t(std::floor(x)), std::max<int64_t>(d[a] - 2, 0));
    f[a] = d[a] > 1 ? x - double(lo[a]) : 0.0;
  }
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    double w = 1.0;
    int64_t at[3];
    for (int a = 0; a < 3; ++a) {
      const bool up = (corner >> a) & 1;
      w *= up ? f[a] : 1.0 - f[a];
      at[a] = std::min<int64_t>(lo[a] + (up ? 1 : 0), d[a] - 1);
    }
    if (w == 0.0) continue;  // a NaN neighbour the point does not reach stays out
    sum += w * volume.value(at[0], at[1], at[2]);
  }
  return sum;
}

PickResult pickVolume(const Volume& volume, const TransferFunction& tf, const ClipRegion& clip,
                      const PickRay& ray, PickRule rule) {
  PickResult none;
  if (volume.empty() || !(glm::length(ray.direction) > 0.0)) return none;
  const glm::dvec3 dir = glm::normalize(ray.direction);
  // Index space: i = D^T (x - origin) / spacing, linear in t, so t carries over.
  const glm::dmat3 toFrame = glm::transpose(volume.direction());
  const glm::dvec3 s = volume.spacing();
  const glm::dvec3 oi = toFrame * (ray.origin - volume.origin()) / s;
  const glm::dvec3 di = toFrame * dir / s;
  RayInterval span{0.0, std::numeric_limits<double>::max()};
  clipToBox(volume.indexDataBox(), oi, di, &span);
  if (clip.active()) {
    const RayInterval kept = clip.clipRay(ray.origin, dir);
    span.near = std::max(span.near, kept.near);
    span.far = std::min(span.far, kept.far);
  }
  if (span.empty() || !std::isfinite(span.far)) return none;
  const double length = span.far - span.near;
  double step = 0.25 * std::min({s.x, s.y, s.z});
  if (!(step > 0.0)) return none;
  step = std::max(step, length / kMaxSteps);
  const int64_t steps = std::max<int64_t>(1, int64_t(std::ceil(length / step)));
  step = length / double(steps);
  auto valueAt = [&](double t) { return trilinearValue(volume, oi + t * di); };
  auto hitAt = [&](double t) {
    PickResult r;
    r.hit = true;
    r.distance = t;
    r.index = oi + t * di;
    r.world = ray.origin + t * dir;
    r.value = valueAt(t);
    return r;
  };

  if (rule == PickRule::MaximumValue) {
    double best = -std::numeric_limits<double>::infinity(), bestT = 0.0;
    for (int64_t n = 0; n <= steps; ++n) {
      const double t = span.near + double(n) * step, v = valueAt(t);
      if (std::isfinite(v) && v > best && tf.alphaAt(v) > 0.0) best = v, bestT = t;
    }
    return std::isfinite(best) ? hitAt(bestT) : none;
  }

  // Optical depth of step n (its midpoint's extinction over its length); NaN is transparent.
  auto depthOf = [&](int64_t n) {
    const double v = valueAt(span.near + (double(n) + 0.5) * step);
    return std::isfinite(v) ? tf.extinctionAt(v) * step : 0.0;
  };
  constexpr double kOpaqueDepth = 14.0;  // transmittance e^-14 ~ 1e-6: nothing behind counts
  double total = 0.0;
  for (int64_t n = 0; n < steps && total < kOpaqueDepth; ++n) total += depthOf(n);
  const double opacity = 1.0 - std::exp(-total);
  if (opacity < kPickMinOpacity) return none;
  // Half the total opacity: transmittance (1 + T_total) / 2, i.e. this optical depth.
  const double half = -std::log(0.5 * (1.0 + std::exp(-total)));
  double before = 0.0;
  for (int64_t n = 0; n < steps; ++n) {
    const double here = depthOf(n);
    if (before + here >= half && here > 0.0) {
      // Extinction is constant across the step: the depth grows linearly within it.
      const double t = span.near + (double(n) + (half - before) / here) * step;
      PickResult r = hitAt(t);
      r.opacity = opacity;
      return r;
    }
    before += here;
  }
  PickResult r = hitAt(span.far);  // rounding left the last bit short
  r.opacity = opacity;
  return r;
}

glm::i64vec3 nearestVoxel(const Volume& volume, const glm::dvec3& index) {
  glm::i64vec3 v;
  for (int a = 0; a < 3; ++a) {
    const double top = double(std::max<int64_t>(volume.dims()[a], 1) - 1);
    v[a] = int64_t(std::llround(std::clamp(index[a], 0.0, top)));
  }
  return v;
}

std::string describePick(const Volume& volume, const PickResult& pick,
                         const std::optional<glm::dvec3>& mark) {
  if (!pick.hit) return "";
  const glm::i64vec3 voxel = nearestVoxel(volume, pick.index);
  char text[240];
  // Lengths in the file's unit when it names one; patient axes say which way they point
  // (DICOM's LPS: x to the left, y to the back, z up).
  const std::string unit = volume.unit().empty() ? "" : " " + volume.unit().substr(0, 16);
  int n = std::snprintf(
      text, sizeof text, "x %.4g  y %.4g  z %.4g%s%s   voxel %lld, %lld, %lld   value %.6g",
      pick.world.x, pick.world.y, pick.world.z, unit.c_str(), volume.patientFrame() ? " (LPS)" : "",
      (long long)voxel.x, (long long)voxel.y, (long long)voxel.z, pick.value);
  if (mark && n > 0 && size_t(n) < sizeof text)
    std::snprintf(text + n, sizeof text - size_t(n), "   %.4g%s from the mark",
                  glm::length(pick.world - *mark), unit.c_str());
  return text;
}

Camera centredOn(const Camera& camera, const glm::dvec3& point) {
  Camera c = camera;
  const glm::dvec3 dir = camera.direction();
  // Perspective: the point's depth, so what is around it keeps its size on screen; parallel:
  // the distance, which sets the scale.
  double d = camera.orthographic ? camera.distance() : glm::dot(point - camera.position, dir);
  if (!(d > 1e-6 * camera.distance())) d = camera.distance();
  c.focalPoint = point;
  c.position = point - dir * d;
  return c;
}

}  // namespace ewa
