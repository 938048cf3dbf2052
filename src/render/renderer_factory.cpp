// createRenderer: splat or shear-warp.
#include "render/renderer_factory.h"

#include "render/shear_warp_renderer.h"
#include "render/splat_renderer.h"

namespace ewa {

std::unique_ptr<Renderer> createRenderer(RendererKind kind, const gl::ShaderLibrary& shaders) {
  if (kind == RendererKind::ShearWarp) return std::make_unique<ShearWarpRenderer>();
  return std::make_unique<SplatRenderer>(shaders);
}

}  // namespace ewa
