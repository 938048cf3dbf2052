// Post-classified slabs: how long a stretch of a pixel's ray the field covers, from the kernels'
// summed weight, ended at the data's box as a ray caster's field ends there. A line-for-line
// mirror of src/core/covered_length.cpp.

uniform mat4 uCameraToIndex;  // camera space to voxel index coordinates (affine)
// The data's box in index coordinates: between the outermost voxel centres (an axis one voxel
// thick: that voxel's extent, +-0.5).
uniform vec3 uBoxLow;
uniform vec3 uBoxHigh;
// Pixel rays: (1 orthographic / 0 perspective, 1 / (ppu or focal pixels), principal point).
uniform vec4 uBoxRay;
const float kBoxUnbounded = 1e30;

// The ray through `pixel` in index coordinates: the point at depth z is x + z * y.
mat2x3 indexRay(vec2 pixel) {
  vec2 q = (pixel - uBoxRay.zw) * uBoxRay.y;
  bool orthographic = uBoxRay.x > 0.5;
  vec3 origin = orthographic ? vec3(q, 0.0) : vec3(0.0);
  vec3 direction = orthographic ? vec3(0.0, 0.0, -1.0) : vec3(q, -1.0);
  return mat2x3((uCameraToIndex * vec4(origin, 1.0)).xyz, mat3(uCameraToIndex) * direction);
}

// The depths [near, far] of `ray` (indexRay) inside the data's box; empty if near > far.
vec2 boxDepths(mat2x3 ray) {
  vec2 kept = vec2(-kBoxUnbounded, kBoxUnbounded);
  for (int axis = 0; axis < 3; ++axis) {
    float o = ray[0][axis], d = ray[1][axis];
    if (abs(d) > 1e-12) {
      float t0 = (uBoxLow[axis] - o) / d, t1 = (uBoxHigh[axis] - o) / d;
      kept = vec2(max(kept.x, min(t0, t1)), min(kept.y, max(t0, t1)));
    } else if (o < uBoxLow[axis] || o > uBoxHigh[axis]) {
      kept.y = -kBoxUnbounded;
    }
  }
  return kept;
}

// World length per unit of depth along the ray through `pixel`.
float rayStretch(vec2 pixel) {
  if (uBoxRay.x > 0.5) return 1.0;
  vec2 q = (pixel - uBoxRay.zw) * uBoxRay.y;
  return sqrt(1.0 + dot(q, q));
}

// The covered length of the ray between depths `a` and `b`, given the kernels' summed weight
// `weight` there (their covered length, which the clip region has cut already) and the depths
// `box` (boxDepths) inside the data's box: the weight inside, none outside, and where a face
// cuts the stretch at most the length inside (`stretch`: world length a unit of depth), so
// the kernels' tails beyond the face add nothing.
float coveredLength(float a, float b, vec2 box, float stretch, float weight) {
  float near = max(a, box.x), far = min(b, box.y);
  if (!(far > near)) return 0.0;
  if (near > a || far < b) return min(weight, (far - near) * stretch);
  return weight;
}
