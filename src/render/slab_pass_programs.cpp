// SlabPassPrograms: slab pass programs compiled per variant on first use.
#include "render/slab_pass_programs.h"

namespace ewa {

gl::VariantFlags SlabPassVariant::flags() const {
  return {{"SLAB_POST", post},
          {"SLAB_PREINTEGRATED", preintegrated},
          {"SLAB_SHADING", shading},
          {"SLAB_FIELD_NORMALS", fieldNormals},
          {"SLAB_RAY_NORMALS", rayNormals},
          {"SLAB_NEIGHBOUR_IN_FRONT", neighbourInFront},
          {"SLAB_SCALED", scaled},
          {"SLAB_QUARTERS", quarters}};
}

SlabPassPrograms::SlabPassPrograms(const gl::ShaderLibrary& shaders) : shaders_(shaders) {
  select(SlabPassVariant{});
}

gl::Program& SlabPassPrograms::select(const SlabPassVariant& variant) {
  return programs_.select(variant.flags(), [&](const std::string& defines) {
    return shaders_.program("fullscreen.vert.glsl", "slab_composite.frag.glsl", defines);
  });
}

}  // namespace ewa
