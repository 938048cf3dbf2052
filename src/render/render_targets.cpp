// RenderTargets: creation of the slab, accumulation and output framebuffers.
#include "render/render_targets.h"

#include <string>

#include "gl/gl_error.h"

namespace ewa {

namespace {

// Half floats where asked: a slab's sums are small (weights of the kernels one slab holds and
// normalized values), and blending half the bytes is what costs on a GPU.
gl::Texture slabImageTexture(int w, int h, bool half) {
  gl::Texture t = gl::Texture::create2D(half ? GL_RGBA16F : GL_RGBA32F, w, h);
  t.setFilter(GL_LINEAR, GL_LINEAR);  // coarser slab images are read bilinearly
  return t;
}

}  // namespace

void RenderTargets::resize(int w, int h, bool paired, bool quarter, bool normals, bool half,
                           bool coarse) {
  quarter = quarter && paired;
  const bool fresh = !(w == width && h == height && output && half == halfSlabs_);
  if (fresh) createImages(w, h, half);
  if (!fresh && paired == pairedSlabs() && quarter == quarters() && normals == normalSums() &&
      coarse == coarseSlabs())
    return;
  slabCoarseFbo = gl::Framebuffer();
  slabOtherCoarseFbo = gl::Framebuffer();
  coarseMarks = gl::Texture();
  slabOtherFbo = gl::Framebuffer();
  slabOther = gl::Texture();
  slabBack = gl::Texture();
  slabOtherBack = gl::Texture();
  slabNormal = gl::Texture();
  if (normals) {
    slabNormal = gl::Texture::create2D(GL_RGBA16F, w, h);
    slabNormal.setFilter(GL_LINEAR, GL_LINEAR);  // coarser slab images are read bilinearly
  }
  if (paired) slabOther = slabImageTexture(w, h, half);
  if (quarter) {
    slabBack = slabImageTexture(w, h, half);
    slabOtherBack = slabImageTexture(w, h, half);
  }
  slabFbo = slabFramebuffer(slab, slabBack, stencil);
  if (paired) slabOtherFbo = slabFramebuffer(slabOther, slabOtherBack, stencil);
  if (coarse) {
    coarseMarks = gl::Texture::create2D(GL_DEPTH24_STENCIL8, w, h);
    slabCoarseFbo = slabFramebuffer(slab, slabBack, coarseMarks);
    if (paired) slabOtherCoarseFbo = slabFramebuffer(slabOther, slabOtherBack, coarseMarks);
  }
  gl::checkGlError("slab images");
}

gl::Framebuffer RenderTargets::slabFramebuffer(const gl::Texture& image, const gl::Texture& back,
                                               const gl::Texture& depth) {
  gl::Framebuffer fbo = gl::Framebuffer::create();
  fbo.attachColor(0, image);
  if (slabNormal) fbo.attachColor(1, slabNormal);
  if (back) fbo.attachColor(2, back);
  fbo.attachDepth(depth, GL_DEPTH_STENCIL_ATTACHMENT);
  fbo.checkComplete();
  return fbo;
}

void RenderTargets::createImages(int w, int h, bool half) {
  // Say which limit a too-large image breaks, before GL fails with a bare error code.
  GLint maxTexture = 0, maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  if (w < 1 || h < 1 || w > maxTexture || h > maxTexture || w > maxViewport[0] ||
      h > maxViewport[1]) {
    throw gl::GlError("image size " + std::to_string(w) + "x" + std::to_string(h) +
                      " is outside this OpenGL's limits (GL_MAX_TEXTURE_SIZE " +
                      std::to_string(maxTexture) + ", GL_MAX_VIEWPORT_DIMS " +
                      std::to_string(maxViewport[0]) + "x" + std::to_string(maxViewport[1]) + ")");
  }
  *this = RenderTargets();  // free the old images first: the new ones may be large
  halfSlabs_ = half;
  slab = slabImageTexture(w, h, half);
  accum = gl::Texture::create2D(GL_RGBA32F, w, h);
  output = gl::Texture::create2D(GL_RGBA8, w, h);
  stencil = gl::Texture::create2D(GL_DEPTH24_STENCIL8, w, h);
  for (gl::Texture* t : {&accum, &output}) t->setFilter(GL_NEAREST, GL_NEAREST);
  accumFbo = gl::Framebuffer::create();
  accumFbo.attachColor(0, accum);
  accumFbo.attachDepth(stencil, GL_DEPTH_STENCIL_ATTACHMENT);
  accumFbo.checkComplete();
  outputFbo = gl::Framebuffer::create();
  outputFbo.attachColor(0, output);
  outputFbo.checkComplete();
  gl::checkGlError("render targets");  // GL_OUT_OF_MEMORY for images too large to allocate
  width = w;
  height = h;
}

}  // namespace ewa
