// SplatPrograms: splat programs compiled per variant on first use.
#include "render/splat_programs.h"

namespace ewa {

unsigned SplatVariant::key() const {
  return (mip ? 1u : 0u) | (post ? 2u : 0u) | (halves ? 4u : 0u) | (clip ? 8u : 0u) |
         (texelBuffers ? 16u : 0u);
}

std::string SplatVariant::defines() const {
  std::string text;
  const auto line = [&](const char* name, bool on) {
    text += std::string("#define ") + name + (on ? " 1\n" : " 0\n");
  };
  line("SPLAT_MIP", mip);
  line("SPLAT_POST", post);
  line("SPLAT_HALVES", halves);
  line("SPLAT_CLIP", clip);
  line("SPLAT_TEXEL_BUFFER", texelBuffers);
  return text;
}

SplatPrograms::SplatPrograms(const gl::ShaderLibrary& shaders) : shaders_(shaders) {
  select(SplatVariant{});
}

void SplatPrograms::select(const SplatVariant& variant) {
  auto found = programs_.find(variant.key());
  if (found == programs_.end()) {
    const std::string defines = variant.defines();
    Pair pair{shaders_.program("splat_point.vert.glsl", "splat.frag.glsl", defines),
              shaders_.program("splat_quad.vert.glsl", "splat.frag.glsl", defines)};
    found = programs_.emplace(variant.key(), std::move(pair)).first;
  }
  current_ = &found->second;
}

}  // namespace ewa
