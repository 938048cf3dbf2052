// SplatRenderer::writeTileSplats and the rest of what the compute splatter takes from the frame:
// its records from the splat shaders' setup, its variant, the classification's state.
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
  // The frame's own variant (clipped frames compile too, though the compute splatter does not
  // draw them), so the footprints come from the same compiled setup.
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

bool SplatRenderer::tileComposite(bool& post, bool& shading) const {
  const RenderSettings& s = frame_.settings;
  post = postClassified(s);
  shading = fieldNormals(s);
  if (s.mode != RenderMode::Composite || s.clip.active() || s.order != CompositeOrder::FrontToBack)
    return false;
  return !post || (quarterSlabs(s) && (shading || !s.lighting.enabled));
}

void SplatRenderer::prepareTileComposite(gl::Program& program) {
  if (!volume_) return;
  setClassifyUniforms(program, frame_.proj, frame_.settings);
  if (pairedSlabs(frame_.settings)) pairTable_.bindUnits(kPairTableUnit, kPairPrefixUnit);
}

}  // namespace ewa
