// The compute splatter's footprint pass: each splat's footprint, optical depth and colour as
// the splat vertex shaders make them (splatSetup), written as tile_ewa.comp.glsl's records.
#define SPLAT_COMPUTE 1
#include "splat_common.glsl"
#include "dispatch_index.glsl"

layout(local_size_x = 64) in;

// Per splat four vec4 (TileEwaSplat): the footprint's box (centre, half extents in pixels),
// (conic, optical depth or post-classified weight at the centre), (depth, depth slope x and y,
// depth sigma), (colour, normalized value).
// A splat not drawn gets zeros: a box of no size, no optical depth.
layout(std430, binding = 6) writeonly buffer TileSplats { vec4 tileSplats[]; };

uniform uint uSplatCount;

void main() {
  uint i = dispatchIndex(64u);
  if (i >= uSplatCount) return;
  Footprint fp;
  float amplitude, value;
  vec3 rgb;
  vec4 box = vec4(0.0), conic = vec4(0.0), depth = vec4(0.0), color = vec4(0.0);
  if (splatSetup(i, fp, amplitude, rgb, value)) {
    box = vec4(fp.center, sqrt(uCutoff * fp.covariance.xz));
    conic = vec4(fp.conic, amplitude);
    depth = vec4(fp.depth, fp.depthSlope, fp.depthSigma);
    color = vec4(rgb, value);
  }
  tileSplats[4u * i] = box;
  tileSplats[4u * i + 1u] = conic;
  tileSplats[4u * i + 2u] = depth;
  tileSplats[4u * i + 3u] = color;
}
