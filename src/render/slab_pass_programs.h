// SlabPassPrograms: the slab pass (shaders/slab_composite.frag.glsl) compiled per variant on
// first use, so each frame's pass over the slab image runs only the code its settings need.
#pragma once

#include <string>

#include "gl/program.h"
#include "gl/program_variants.h"
#include "gl/shader_library.h"

namespace ewa {

// What a frame's slab pass computes, fixed at compile time: llvmpipe runs both sides of a
// branch on a uniform, so the unused paths (shading, the pre-integrated segments, field
// normals) cost every pixel of every slab there.
struct SlabPassVariant {
  bool post = false;              // post-classification: the slab holds values and weights
  bool preintegrated = false;     // post, pre-integrated between slabs (paired slab images)
  bool shading = false;           // post, shaded with the head light
  bool fieldNormals = false;      // shaded, pre-integrated: normals from the field's gradient
  bool rayNormals = false;        // shaded: normals from the gradient texture along the ray
  bool neighbourInFront = false;  // pre-integrated front to back: the slab drawn before is nearer
  bool scaled = false;            // the slab's or its neighbour's image is coarser (bilinear)
  bool quarters = false;          // pre-integrated with four values a slab (two images a slab)

  gl::VariantFlags flags() const;
  unsigned key() const { return gl::variantKey(flags()); }
  // The #define lines slab_composite.frag.glsl reads.
  std::string defines() const { return gl::variantDefines(flags()); }
};

class SlabPassPrograms {
 public:
  // Compiles the default variant at once, so a broken shader fails here, not in a frame.
  explicit SlabPassPrograms(const gl::ShaderLibrary& shaders);

  // The program of `variant`, compiled the first time (throws GlError on failure); the
  // reference stays valid while this object lives.
  gl::Program& select(const SlabPassVariant& variant);
  // Variants compiled so far (tests).
  size_t compiled() const { return programs_.compiled(); }

 private:
  const gl::ShaderLibrary& shaders_;
  gl::ProgramVariants<gl::Program> programs_;
};

}  // namespace ewa
