// SplatProgramSet: compiles the programs every splat renderer needs; variants come on first use.
#include "render/splat_program_set.h"

namespace ewa {

SplatProgramSet::SplatProgramSet(const gl::ShaderLibrary& library)
    : shaders(library),
      splat(shaders),
      slab(shaders),
      mark(shaders.program("fullscreen.vert.glsl", "opacity_mark.frag.glsl")),
      final(shaders.program("fullscreen.vert.glsl", "final_composite.frag.glsl")),
      box(shaders.program("bounds_box.vert.glsl", "bounds_box.frag.glsl")) {}

}  // namespace ewa
