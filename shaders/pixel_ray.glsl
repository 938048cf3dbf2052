// A pixel's ray in camera space, shared by the clip region and the data's box (set by
// src/render/clip_uniforms.cpp): the point at depth z is z * (offset, -1) in perspective,
// (offset, -z) in parallel projection.
// (1 orthographic / 0 perspective, 1 / (ppu or focal pixels), principal point).
uniform vec4 uPixelRay;

bool orthographicRays() { return uPixelRay.x > 0.5; }

// The ray's lateral offset through `pixel`: world units (orthographic) or per unit of depth.
vec2 rayOffset(vec2 pixel) { return (pixel - uPixelRay.zw) * uPixelRay.y; }
