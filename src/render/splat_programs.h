// SplatPrograms: the splat point and quad programs, one pair per variant (MIP, post-classified,
// halves, clipped, texel buffers), compiled on first use so each frame runs only the code its
// settings need.
#pragma once

#include <array>
#include <string>

#include "gl/program.h"
#include "gl/program_variants.h"
#include "gl/shader_library.h"

namespace ewa {

// What a frame's splat fragments compute, fixed at compile time (shaders/splat_variant.glsl).
struct SplatVariant {
  bool mip = false;           // maximum intensity projection
  bool post = false;          // post-classification: values and weights, not colour and opacity
  bool halves = false;        // post, pre-integrated between slabs: each slab's two halves apart
  bool quarters = false;      // halves, each split again: four depth samples a slab
  bool clip = false;          // a crop box or clipping planes cut the kernels
  bool texelBuffers = false;  // splat records and attributes read from texel buffers
  bool erfSeries = false;     // the depth profile is cut within erfSeries' reach (profileErf)

  gl::VariantFlags flags() const;
  unsigned key() const { return gl::variantKey(flags()); }
  // The #define lines shaders/splat_variant.glsl reads.
  std::string defines() const { return gl::variantDefines(flags()); }
};

class SplatPrograms {
 public:
  // Compiles the default variant at once, so a broken shader fails here, not in a frame.
  explicit SplatPrograms(const gl::ShaderLibrary& shaders);

  // Makes `variant` the current one, compiling it the first time (throws GlError on failure).
  void select(const SplatVariant& variant);
  gl::Program& point() { return current_->point; }
  gl::Program& quad() { return current_->quad; }
  // Both programs of the current variant, for the uniforms they share.
  std::array<gl::Program*, 2> both() { return {&current_->point, &current_->quad}; }
  // Variants compiled so far (tests).
  size_t compiled() const { return programs_.compiled(); }

 private:
  struct Pair {
    gl::Program point;
    gl::Program quad;
  };
  const gl::ShaderLibrary& shaders_;
  gl::ProgramVariants<Pair> programs_;
  Pair* current_ = nullptr;
};

}  // namespace ewa
