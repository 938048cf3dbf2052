// The bounding box's fragments for the occlusion query: only whether they pass the stencil
// counts (colour writes are masked while it is drawn). A fragment is left out whose ray crosses
// nothing the planes keep inside the (grown) box, or nothing at or behind uFromDepth (the slabs
// still to come, less the kernels' reach): the splat shaders give such a pixel no share of
// those kernels (clippedDepths, the same planes), so it can never turn opaque.
#include "clip_region.glsl"
#include "covered_length.glsl"

uniform float uFromDepth;

out vec4 outColor;

void main() {
  vec2 box = boxDepths(indexRay(gl_FragCoord.xy));
  vec2 kept = clippedDepths(gl_FragCoord.xy);
  if (max(max(box.x, kept.x), uFromDepth) > min(box.y, kept.y)) discard;
  outColor = vec4(0.0);
}
