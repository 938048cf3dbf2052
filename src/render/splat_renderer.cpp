// SplatRenderer: classification into splats, slab sorting, splat drawing and compositing.
#include "render/splat_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_error.h"
#include "gl/scoped_bind.h"

namespace ewa {

namespace {
constexpr int kTransferSamples = 4096;
}  // namespace

SplatRenderer::SplatRenderer(const gl::ShaderLibrary& shaders)
    : pointProgram_(shaders.program("splat_point.vert.glsl", "splat.frag.glsl")),
      quadProgram_(shaders.program("splat_quad.vert.glsl", "splat.frag.glsl")),
      slabProgram_(shaders.program("fullscreen.vert.glsl", "slab_composite.frag.glsl")),
      finalProgram_(shaders.program("fullscreen.vert.glsl", "final_composite.frag.glsl")),
      emptyVao_(gl::VertexArray::create()),
      transferTexture_(gl::Texture::create1D(GL_RGBA32F, kTransferSamples)) {
  GLfloat range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, range);
  glPointSizeLimit_ = pointSizeLimit_ = std::max(1.0f, range[1]);
  transferTexture_.setFilter(GL_LINEAR, GL_LINEAR);
  transferTexture_.setWrap(GL_CLAMP_TO_EDGE);
}

void SplatRenderer::setPointSizeLimit(float limit) {
  pointSizeLimit_ = std::clamp(limit, 1.0f, glPointSizeLimit_);
}

void SplatRenderer::setVolume(const Volume& volume) {
  volume_ = &volume;
  splatsDirty_ = true;
}

void SplatRenderer::setTransferFunction(const TransferFunction& tf) {
  tf_ = tf;
  splatsDirty_ = true;
}

void SplatRenderer::rebuildSplats() {
  splatsDirty_ = false;
  uploadTransferTexture();
  splats_ = SplatSet::build(*volume_, [this](double v) { return tf_.alphaAt(v) > 0.0; });
  uploadSplats();
}

void SplatRenderer::uploadTransferTexture() {
  const double lo = volume_->minValue(), hi = volume_->maxValue();
  const std::vector<glm::vec4> table = tf_.bake(lo, hi, kTransferSamples);
  transferTexture_.subImage1D(0, 0, kTransferSamples, GL_RGBA, GL_FLOAT, table.data());
}

void SplatRenderer::updateTransferTexture(const TransferFunction& tf) {
  tf_ = tf;
  if (volume_) uploadTransferTexture();
}

void SplatRenderer::setSplats(SplatSet splats) {
  splats_ = std::move(splats);
  splatsDirty_ = false;
  uploadSplats();
}

void SplatRenderer::uploadSplats() {
  const auto bytes = GLsizeiptr(std::max<size_t>(1, splats_.size()) * sizeof(PackedSplat));
  splatBuffer_.setData(bytes, splats_.size() ? splats_.splats().data() : nullptr, GL_STATIC_DRAW);
  orderBuffer_.setData(GLsizeiptr(std::max<size_t>(1, splats_.size()) * sizeof(uint32_t)),
                       nullptr, GL_STREAM_DRAW);
}

double SplatRenderer::footprintRadiusBound(const Projection& proj, const RenderSettings& settings,
                                           double nearestDepth) const {
  const glm::dvec3& sp = volume_->spacing();
  const double sigma = std::max({sp.x, sp.y, sp.z});
  const double minSpacing = std::min({sp.x, sp.y, sp.z});
  double ppu = proj.pixelsPerUnit;
  if (!proj.orthographic) {
    // Off-axis kernels stretch by up to 1 + tan^2 of the half diagonal angle.
    const double t2 = (proj.width * proj.width + proj.height * proj.height) /
                      (4.0 * proj.focalPixels * proj.focalPixels);
    ppu = proj.focalPixels / nearestDepth * (1.0 + t2);
  }
  const double swan = settings.filter == FilterMode::Swan ? sigma / minSpacing : 0.0;
  return std::sqrt(settings.cutoff) * (sigma * ppu + 1.0 + swan);
}

void SplatRenderer::setCommonUniforms(gl::Program& p, const Camera& camera, const Projection& proj,
                                      const RenderSettings& settings) {
  const glm::dvec3& sp = volume_->spacing();
  const FootprintParams params = footprintParams(settings, sp);
  p.setMat4("uView", glm::mat4(camera.viewMatrix()));
  p.setMat3("uCovariance", glm::mat3(cameraCovariance(camera.rotation(), sp)));
  p.setVec3("uOrigin", glm::vec3(volume_->origin()));
  p.setVec3("uSpacing", glm::vec3(sp));
  p.setFloat("uVoxelVolume", float(sp.x * sp.y * sp.z));
  p.setFloat("uKernelRadius", float(std::sqrt(settings.cutoff) * std::max({sp.x, sp.y, sp.z})));
  p.setInt("uOrthographic", proj.orthographic ? 1 : 0);
  p.setFloat("uFocalPixels", float(proj.focalPixels));
  p.setFloat("uPixelsPerUnit", float(proj.pixelsPerUnit));
  p.setVec2("uViewport", glm::vec2(proj.width, proj.height));
  p.setInt("uFilter", int(params.filter));
  p.setFloat("uCutoff", float(params.cutoff));
  p.setFloat("uMinSpacing", float(params.minSpacing));
  p.setFloat("uNearDepth", float(params.nearDepth));
  p.setFloat("uPointSizeLimit", pointSizeLimit_);
  p.setInt("uTransfer", 0);
}

void SplatRenderer::drawSplats(const Slab& slab, bool quads) {
  pointProgram_.setUInt("uFirst", slab.first);
  glUseProgram(pointProgram_.id());
  glDrawArrays(GL_POINTS, 0, GLsizei(slab.count));
  if (quads) {
    quadProgram_.setUInt("uFirst", slab.first);
    glUseProgram(quadProgram_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(slab.count));
  }
}

void SplatRenderer::render(const Camera& camera, const RenderSettings& settings, int width,
                           int height) {
  const auto start = std::chrono::steady_clock::now();
  targets_.resize(width, height);
  stats_ = RenderStats{};
  const GLfloat zero[4] = {0, 0, 0, 0};
  targets_.accumFbo.clearColor(0, zero);
  if (volume_ && splatsDirty_) rebuildSplats();
  const Projection proj = camera.projection(width, height);
  if (volume_ && splats_.size() > 0 && camera.valid()) {
    const glm::dvec3& sp = volume_->spacing();
    const FootprintParams params = footprintParams(settings, sp);
    // X-ray sums every splat into one buffer: a single slab of unbounded thickness.
    const double thickness = settings.mode == RenderMode::XRay
                                 ? 1e30
                                 : std::max(1e-3, settings.slabThickness) * params.minSpacing;
    partition_.build(splats_, volume_->origin(), sp, camera.viewMatrix(), thickness,
                     params.nearDepth);
    const auto& order = partition_.order();
    stats_.splatsTotal = splats_.size();
    stats_.splatsDrawn = order.size();
    stats_.slabs = partition_.slabs().size();
    if (!order.empty()) {
      orderBuffer_.setSubData(0, GLsizeiptr(order.size() * sizeof(uint32_t)), order.data());
      const double nearest = partition_.slabs().front().nearDepth;
      stats_.quadPass = 2.0 * footprintRadiusBound(proj, settings, nearest) + 0.5 > pointSizeLimit_;
      setCommonUniforms(pointProgram_, camera, proj, settings);
      setCommonUniforms(quadProgram_, camera, proj, settings);
      splatBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
      orderBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
      transferTexture_.bindUnit(0);
      targets_.slab.bindUnit(1);
      slabProgram_.setInt("uSlab", 1);
      glBindVertexArray(emptyVao_.id());
      glViewport(0, 0, width, height);
      glEnable(GL_PROGRAM_POINT_SIZE);
      glDisable(GL_DEPTH_TEST);
      glEnable(GL_BLEND);
      for (const Slab& slab : partition_.slabs()) {
        // Inside a slab: order-independent sums of optical depth and emitted light.
        glBindFramebuffer(GL_FRAMEBUFFER, targets_.slabFbo.id());
        targets_.slabFbo.clearColor(0, zero);
        glBlendFunc(GL_ONE, GL_ONE);
        drawSplats(slab, stats_.quadPass);
        if (settings.mode == RenderMode::XRay) break;
        // Between slabs: front-to-back "under" compositing of 1 - exp(-depth).
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindFramebuffer(GL_FRAMEBUFFER, targets_.accumFbo.id());
        glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_ONE);
        glUseProgram(slabProgram_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
      if (settings.mode == RenderMode::XRay) {
        glBindFramebuffer(GL_FRAMEBUFFER, targets_.accumFbo.id());
        glBlendFunc(GL_ONE, GL_ZERO);
        glUseProgram(slabProgram_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
      glDisable(GL_BLEND);
    }
  }
  glBindVertexArray(emptyVao_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.outputFbo.id());
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  targets_.accum.bindUnit(2);
  finalProgram_.setInt("uImage", 2);
  finalProgram_.setVec3("uBackground", glm::vec3(settings.background));
  glUseProgram(finalProgram_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  glFinish();
  gl::checkGlError("SplatRenderer::render");
  stats_.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

Image8 SplatRenderer::readImage() const {
  Image8 img;
  img.width = targets_.width;
  img.height = targets_.height;
  img.channels = 3;
  std::vector<uint8_t> rgba(size_t(img.width) * img.height * 4);
  if (rgba.empty()) return img;
  targets_.output.getImage(0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  img.pixels.resize(size_t(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y) {
    const uint8_t* src = rgba.data() + size_t(img.height - 1 - y) * img.width * 4;
    uint8_t* dst = img.pixels.data() + size_t(y) * img.width * 3;
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
  }
  return img;
}

std::vector<float> SplatRenderer::readOpticalDepth() const {
  std::vector<float> rgba(size_t(targets_.width) * targets_.height * 4);
  if (rgba.empty()) return {};
  targets_.slab.getImage(0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  std::vector<float> depth(rgba.size() / 4);
  for (size_t p = 0; p < depth.size(); ++p) depth[p] = rgba[p * 4 + 3];
  return depth;
}

}  // namespace ewa
