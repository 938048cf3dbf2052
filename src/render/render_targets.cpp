// RenderTargets: creation of the slab, accumulation and output framebuffers.
#include "render/render_targets.h"

namespace ewa {

void RenderTargets::resize(int w, int h) {
  if (w == width && h == height && output) return;
  slab = gl::Texture::create2D(GL_RGBA32F, w, h);
  accum = gl::Texture::create2D(GL_RGBA32F, w, h);
  output = gl::Texture::create2D(GL_RGBA8, w, h);
  stencil = gl::Texture::create2D(GL_DEPTH24_STENCIL8, w, h);
  for (gl::Texture* t : {&slab, &accum, &output}) t->setFilter(GL_NEAREST, GL_NEAREST);
  slabFbo = gl::Framebuffer::create();
  slabFbo.attachColor(0, slab);
  slabFbo.attachDepth(stencil, GL_DEPTH_STENCIL_ATTACHMENT);
  slabFbo.checkComplete();
  accumFbo = gl::Framebuffer::create();
  accumFbo.attachColor(0, accum);
  accumFbo.attachDepth(stencil, GL_DEPTH_STENCIL_ATTACHMENT);
  accumFbo.checkComplete();
  outputFbo = gl::Framebuffer::create();
  outputFbo.attachColor(0, output);
  outputFbo.checkComplete();
  width = w;
  height = h;
}

}  // namespace ewa
