// Post-classified slabs: how long a stretch of a pixel's ray the field covers, from the kernels'
// summed weight, ended at the data's box as a ray caster's field ends there. A line-for-line
// mirror of src/core/covered_length.cpp.
#include "pixel_ray.glsl"

uniform mat4 uCameraToIndex;  // camera space to voxel index coordinates (affine)
// The data's box in index coordinates: between the outermost voxel centres (an axis one voxel
// thick: that voxel's extent, +-0.5).
uniform vec3 uBoxLow;
uniform vec3 uBoxHigh;

// The ray through `pixel` in index coordinates: the point at depth z is x + z * y.
mat2x3 indexRay(vec2 pixel) {
  vec2 q = rayOffset(pixel);
  bool orthographic = orthographicRays();
  vec3 origin = orthographic ? vec3(q, 0.0) : vec3(0.0);
  vec3 direction = orthographic ? vec3(0.0, 0.0, -1.0) : vec3(q, -1.0);
  return mat2x3((uCameraToIndex * vec4(origin, 1.0)).xyz, mat3(uCameraToIndex) * direction);
}

// The depths [near, far] of `ray` (indexRay) inside the data's box; empty if near > far. A ray
// parallel to a face gets infinite slab bounds (of one sign: outside it).
vec2 boxDepths(mat2x3 ray) {
  vec3 d = ray[1];
  vec3 inv = 1.0 / mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
  vec3 t0 = (uBoxLow - ray[0]) * inv, t1 = (uBoxHigh - ray[0]) * inv;
  vec3 lo = min(t0, t1), hi = max(t0, t1);
  return vec2(max(max(lo.x, lo.y), lo.z), min(min(hi.x, hi.y), hi.z));
}

// World length per unit of depth along the ray through `pixel`.
float rayStretch(vec2 pixel) {
  if (orthographicRays()) return 1.0;
  vec2 q = rayOffset(pixel);
  return sqrt(1.0 + dot(q, q));
}

// The covered length of the ray between depths `a` and `b`, given the kernels' summed weight
// `weight` there (their covered length, which the clip region has cut already) and the depths
// `box` (boxDepths) inside the data's box: the weight inside, none outside, and where a face
// cuts the stretch at most the length inside (`stretch`: world length a unit of depth), so
// the kernels' tails beyond the face add nothing.
float coveredLength(float a, float b, vec2 box, float stretch, float weight) {
  float near = max(a, box.x), far = min(b, box.y);
  float inside = max(far - near, 0.0) * stretch;
  // Uncut: far - near is b - a, and the weight is kept as it is.
  return (near > a || far < b) ? min(weight, inside) : weight;
}
