// SplatPrograms: splat programs compiled per variant on first use.
#include "render/splat_programs.h"

namespace ewa {

gl::VariantFlags SplatVariant::flags() const {
  return {{"SPLAT_MIP", mip},
          {"SPLAT_POST", post},
          {"SPLAT_HALVES", halves},
          {"SPLAT_QUARTERS", quarters},
          {"SPLAT_CLIP", clip},
          {"SPLAT_TEXEL_BUFFER", texelBuffers},
          {"SPLAT_ERF_SERIES", erfSeries}};
}

SplatPrograms::SplatPrograms(const gl::ShaderLibrary& shaders) : shaders_(shaders) {
  select(SplatVariant{});
}

void SplatPrograms::select(const SplatVariant& variant) {
  current_ = &programs_.select(variant.flags(), [&](const std::string& defines) {
    return Pair{shaders_.program("splat_point.vert.glsl", "splat.frag.glsl", defines),
                shaders_.program("splat_quad.vert.glsl", "splat.frag.glsl", defines)};
  });
}

}  // namespace ewa
