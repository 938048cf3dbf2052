// SplatRenderer::writeTileSplats: the compute splatter's records from the splat shaders' setup.
#include <stdexcept>

#include "gl/gl_error.h"
#include "render/splat_renderer.h"
#include "render/tile_ewa_splatter.h"

namespace ewa {

void SplatRenderer::writeTileSplats(gl::Buffer& out) {
  const size_t count = classified_.splats.size();
  if (!volume_ || count == 0) return;
  if (out.size() < GLsizeiptr(count * sizeof(TileEwaSplat)))
    throw std::invalid_argument("writeTileSplats: the buffer holds fewer records than splats");
  // The frame's own variant (post-classified or clipped frames compile too, though the compute
  // splatter draws neither), so the footprints come from the same compiled setup.
  const SplatVariant variant = splatVariant(frame_.settings, frame_.texelBuffers);
  if (!tileSplatPass_ || tileSplatVariant_ != variant.key()) {
    tileSplatPass_ = shaders_.computeProgram("tile_ewa_footprints.comp.glsl", variant.defines());
    tileSplatVariant_ = variant.key();
  }
  gl::Program& pass = *tileSplatPass_;
  setCommonUniforms(pass, frame_.camera, frame_.proj, frame_.settings);
  pass.setUInt("uSplatCount", GLuint(count));
  bindFrameState();
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  gl::dispatchOver(pass, count, 64);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  gl::checkGlError("tile splat records");
}

}  // namespace ewa
