// createRenderer: splat or shear-warp.
#include "render/renderer_factory.h"

#include "render/shear_warp_renderer.h"
#include "render/splat_renderer.h"

namespace ewa {

std::unique_ptr<Renderer> createRenderer(RendererKind kind, const gl::ShaderLibrary& shaders,
                                         std::shared_ptr<SplatProgramSet>* sharedPrograms) {
  if (kind == RendererKind::ShearWarp) return std::make_unique<ShearWarpRenderer>();
  if (!sharedPrograms) return std::make_unique<SplatRenderer>(shaders);
  if (!*sharedPrograms) *sharedPrograms = std::make_shared<SplatProgramSet>(shaders);
  return std::make_unique<SplatRenderer>(shaders, *sharedPrograms);
}

}  // namespace ewa
