// Picking: which point of the volume a pixel of the picture shows, found along its ray on the CPU.
#pragma once

#include <glm/ext/vector_int3_sized.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa {

// How the point a ray shows is chosen, by render mode.
enum class PickRule {
  // Composite and X-ray: where the opacity accumulated front to back reaches half the ray's
  // total (the median depth of what the pixel shows: the surface of an opaque object, the
  // middle of a haze). Rays whose total opacity stays under kPickMinOpacity show nothing.
  Opacity,
  // MIP: where the largest value along the ray lies, among those the transfer function shows
  // (opacity > 0: the voxels MIP draws).
  MaximumValue,
};

// A ray's total opacity below this shows nothing worth naming (about 1% of the background).
inline constexpr double kPickMinOpacity = 0.01;

struct PickResult {
  bool hit = false;
  glm::dvec3 world{0.0};  // the point in world (patient) coordinates
  glm::dvec3 index{0.0};  // the point in continuous voxel index coordinates (i, j, k)
  double value = 0.0;     // the data's trilinear value there
  double opacity = 0.0;   // the ray's total opacity (Opacity rule; 0 for MaximumValue)
  double distance = 0.0;  // along the ray from the eye (perspective) or the view plane
};

// A ray in world space: origin + t * direction, t >= 0, direction of unit length.
struct PickRay {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

// The ray through `point` of a width x height picture of `camera`, in window coordinates:
// x right, y down from the top-left corner, (0.5, 0.5) the centre of the top-left pixel (a
// cursor position, or a pixel's column and row plus a half). Orthographic rays start on the
// plane through the camera's position.
PickRay pickRay(const Camera& camera, int width, int height, const glm::dvec2& point);

// Where world point `p` appears in that picture, in the same window coordinates (the inverse of
// pickRay); nullopt for a point at or behind the eye of a perspective camera.
std::optional<glm::dvec2> windowPoint(const Camera& camera, int width, int height,
                                      const glm::dvec3& p);

// The point `ray` shows through the volume's field (trilinear between voxel centres, within the
// data's box and `clip`), classified by `tf`, marched in steps of a quarter of the smallest
// voxel spacing. A ray that misses the box, or shows nothing, gives hit == false.
PickResult pickVolume(const Volume& volume, const TransferFunction& tf, const ClipRegion& clip,
                      const PickRay& ray, PickRule rule = PickRule::Opacity);

// Trilinear value at continuous index coordinates inside the grid (clamped to it); NaN voxels
// count as NaN.
double trilinearValue(const Volume& volume, const glm::dvec3& index);

// The voxel nearest to continuous index coordinates, inside the grid.
glm::i64vec3 nearestVoxel(const Volume& volume, const glm::dvec3& index);

// One line naming a pick for people: "x 12.3  y -4.5  z 60.1   voxel 120, 88, 40   value
// 87.25" (the volume's unit, " mm", and " (LPS)" for patient axes after the coordinates), with
// "   23.4 mm from the mark" when `mark` (a world point) is given; "" for a miss.
std::string describePick(const Volume& volume, const PickResult& pick,
                         const std::optional<glm::dvec3>& mark = std::nullopt);

// The camera moved to orbit `point`: it becomes the focal point, in the middle of the view, at
// the distance the eye had from it, looking the way the camera looked (view-up kept). What a
// double-click in the window does.
Camera centredOn(const Camera& camera, const glm::dvec3& point);

}  // namespace ewa
