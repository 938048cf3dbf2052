// ClipRegion: half-spaces of the crop box and clipping planes, containment, clipped rays, parsing.
#include "core/clip_region.h"

#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <sstream>

namespace ewa {

double HalfSpace::distance(const glm::dvec3& x) const {
  return glm::dot(normal, x) + offset;
}

HalfSpace transformed(const HalfSpace& h, const glm::dmat4& rigid) {
  // x' = R x + t: dot(R n, x') + (offset - dot(R n, t)) = dot(n, x) + offset.
  const glm::dvec3 n = glm::dmat3(rigid) * h.normal;
  const glm::dvec3 t(rigid[3]);
  return HalfSpace{n, h.offset - glm::dot(n, t)};
}

bool operator==(const ClipPlane& a, const ClipPlane& b) {
  return a.point == b.point && a.normal == b.normal && a.enabled == b.enabled;
}

bool ClipRegion::operator==(const ClipRegion& o) const {
  return cropEnabled == o.cropEnabled && cropMin == o.cropMin && cropMax == o.cropMax &&
         planes == o.planes;
}

bool ClipRegion::active() const {
  return !halfSpaces().empty();
}

std::vector<HalfSpace> ClipRegion::halfSpaces() const {
  std::vector<HalfSpace> out;
  if (cropEnabled) {
    for (int a = 0; a < 3; ++a) {
      glm::dvec3 n(0.0);
      n[a] = 1.0;
      out.push_back({n, -cropMin[a]});  // x >= min
      out.push_back({-n, cropMax[a]});  // x <= max
    }
  }
  for (size_t i = 0; i < planes.size() && i < kMaxPlanes; ++i) {
    const ClipPlane& p = planes[i];
    const double len = glm::length(p.normal);
    if (!p.enabled || !(len > 0.0) || !std::isfinite(len)) continue;
    const glm::dvec3 n = p.normal / len;
    out.push_back({n, -glm::dot(n, p.point)});
  }
  return out;
}

bool ClipRegion::contains(const glm::dvec3& world) const {
  for (const HalfSpace& h : halfSpaces())
    if (h.distance(world) < 0.0) return false;
  return true;
}

void clipRayBy(const HalfSpace& h, const glm::dvec3& origin, const glm::dvec3& direction,
               RayInterval* span) {
  // dot(n, o + t d) + offset >= 0  <=>  a t + b >= 0.
  const double a = glm::dot(h.normal, direction), b = h.distance(origin);
  if (a > 0.0)
    span->near = std::max(span->near, -b / a);
  else if (a < 0.0)
    span->far = std::min(span->far, -b / a);
  else if (b < 0.0)
    *span = RayInterval{1.0, 0.0};  // parallel and outside: nothing kept
}

RayInterval ClipRegion::clipRay(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                                double tMax) const {
  RayInterval span{tMin, tMax};
  for (const HalfSpace& h : halfSpaces()) clipRayBy(h, origin, direction, &span);
  return span;
}

namespace {

// Exactly `count` comma-separated finite numbers, or a problem.
std::string parseNumbers(const std::string& text, size_t count, std::vector<double>* out) {
  out->clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(v))
      return "'" + item + "' is not a finite number";
    out->push_back(v);
  }
  if (!text.empty() && text.back() == ',') return "a number is missing after the last comma";
  if (out->size() != count)
    return "expected " + std::to_string(count) + " comma-separated numbers, got " +
           std::to_string(out->size());
  return "";
}

}  // namespace

std::string parseCropBox(const std::string& text, ClipRegion* region) {
  std::vector<double> v;
  if (std::string e = parseNumbers(text, 6, &v); !e.empty())
    return "--crop X0,X1,Y0,Y1,Z0,Z1: " + e;
  for (int a = 0; a < 3; ++a)
    if (!(v[2 * a] < v[2 * a + 1]))
      return std::string("--crop X0,X1,Y0,Y1,Z0,Z1: ") + "XYZ"[a] + "0 must be less than " +
             "XYZ"[a] + "1";
  region->cropEnabled = true;
  region->cropMin = {v[0], v[2], v[4]};
  region->cropMax = {v[1], v[3], v[5]};
  return "";
}

std::string parseClipPlane(const std::string& text, ClipRegion* region) {
  std::vector<double> v;
  if (std::string e = parseNumbers(text, 6, &v); !e.empty())
    return "--clip-plane PX,PY,PZ,NX,NY,NZ: " + e;
  const glm::dvec3 n(v[3], v[4], v[5]);
  if (!(glm::length(n) > 0.0)) return "--clip-plane PX,PY,PZ,NX,NY,NZ: the normal is zero";
  if (region->planes.size() >= ClipRegion::kMaxPlanes)
    return "--clip-plane: at most " + std::to_string(ClipRegion::kMaxPlanes) + " planes";
  region->planes.push_back({glm::dvec3(v[0], v[1], v[2]), n, true});
  return "";
}

}  // namespace ewa
