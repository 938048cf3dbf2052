// The splat programs' variant, fixed when they are compiled (src/render/splat_programs.cpp):
// llvmpipe runs both sides of a branch on a uniform, so the unused paths must not be there.
#ifndef SPLAT_MIP
#define SPLAT_MIP 0
#endif
#ifndef SPLAT_POST
#define SPLAT_POST 0
#endif
#ifndef SPLAT_HALVES
#define SPLAT_HALVES 0
#endif
#ifndef SPLAT_QUARTERS
#define SPLAT_QUARTERS 0
#endif
#ifndef SPLAT_CLIP
#define SPLAT_CLIP 0
#endif
#ifndef SPLAT_TEXEL_BUFFER
#define SPLAT_TEXEL_BUFFER 0  // splat records in texel buffers (splat_common.glsl)
#endif
const bool kMip = SPLAT_MIP != 0;        // maximum intensity: the value, maximized
const bool kPost = SPLAT_POST != 0;      // post-classification: values and weights summed
const bool kHalves = SPLAT_HALVES != 0;  // post, pre-integrated: a slab's two halves apart
// with halves: each half split again, four depth samples a slab (two images)
const bool kQuarters = SPLAT_QUARTERS != 0 && kHalves;
const bool kClip = SPLAT_CLIP != 0;      // a crop box or clipping planes are in force
