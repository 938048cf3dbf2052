// createRenderer: the renderer a RendererKind names, behind the Renderer interface.
#pragma once

#include <memory>

#include "gl/shader_library.h"
#include "render/renderer.h"

namespace ewa {

struct SplatProgramSet;

// A GL 4.5 context must be current (the splat renderer builds its shaders now, the shear-warp
// renderer makes its output texture on the first render). `sharedPrograms`: splat renderers made
// with the same pointer share their programs (made with the first; SplatProgramSet).
std::unique_ptr<Renderer> createRenderer(
    RendererKind kind, const gl::ShaderLibrary& shaders,
    std::shared_ptr<SplatProgramSet>* sharedPrograms = nullptr);

}  // namespace ewa
