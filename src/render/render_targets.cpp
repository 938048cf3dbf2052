// RenderTargets: creation of the slab, accumulation and output framebuffers.
#include "render/render_targets.h"

#include <string>

#include "gl/gl_error.h"

namespace ewa {

void RenderTargets::resize(int w, int h, bool paired) {
  if (!(w == width && h == height && output)) createImages(w, h);
  if (paired == pairedSlabs()) return;
  slabOtherFbo = gl::Framebuffer();
  slabOther = gl::Texture();
  if (!paired) return;
  slabOther = gl::Texture::create2D(GL_RGBA32F, w, h);
  slabOther.setFilter(GL_LINEAR, GL_LINEAR);  // coarser slab images are read bilinearly
  slabOtherFbo = gl::Framebuffer::create();
  slabOtherFbo.attachColor(0, slabOther);
  slabOtherFbo.attachColor(1, slabNormal);
  slabOtherFbo.attachDepth(stencil, GL_DEPTH_STENCIL_ATTACHMENT);
  slabOtherFbo.checkComplete();
  gl::checkGlError("second slab image");
}

void RenderTargets::createImages(int w, int h) {
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
  slab = gl::Texture::create2D(GL_RGBA32F, w, h);
  slabNormal = gl::Texture::create2D(GL_RGBA16F, w, h);
  accum = gl::Texture::create2D(GL_RGBA32F, w, h);
  output = gl::Texture::create2D(GL_RGBA8, w, h);
  stencil = gl::Texture::create2D(GL_DEPTH24_STENCIL8, w, h);
  // Coarser slab images (slab_image_scale.h) are read bilinearly; full ones by texelFetch.
  for (gl::Texture* t : {&slab, &slabNormal}) t->setFilter(GL_LINEAR, GL_LINEAR);
  for (gl::Texture* t : {&accum, &output}) t->setFilter(GL_NEAREST, GL_NEAREST);
  slabFbo = gl::Framebuffer::create();
  slabFbo.attachColor(0, slab);
  slabFbo.attachColor(1, slabNormal);
  slabFbo.attachDepth(stencil, GL_DEPTH_STENCIL_ATTACHMENT);
  slabFbo.checkComplete();
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
