// ImagePresenter: copies the renderer's output texture to the window's default framebuffer.
#include "ui/image_presenter.h"

#include "gl/gl_api.h"
#include "gl/texture.h"

namespace ewa {

ImagePresenter::ImagePresenter() : source_(gl::Framebuffer::create()) {
  glNamedFramebufferReadBuffer(source_.id(), GL_COLOR_ATTACHMENT0);
}

void ImagePresenter::present(unsigned texture, int texWidth, int texHeight, int fbWidth,
                             int fbHeight) {
  // Blits obey the scissor test; ImGui restores its state, but do not depend on anyone else's.
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, fbWidth, fbHeight);
  if (texture == 0 || texWidth <= 0 || texHeight <= 0) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  // Attached on every call: the renderer replaces its texture when the size changes, and a
  // new texture may reuse a deleted one's name, so comparing names could keep a stale image.
  glNamedFramebufferTexture(source_.id(), GL_COLOR_ATTACHMENT0, texture, 0);
  // Same size (the usual case, the image is rendered at the framebuffer size): an exact copy.
  const bool sameSize = texWidth == fbWidth && texHeight == fbHeight;
  if (sameSize) warmedExactCopy_ = true;
  glBlitNamedFramebuffer(source_.id(), 0, 0, 0, texWidth, texHeight, 0, 0, fbWidth, fbHeight,
                         GL_COLOR_BUFFER_BIT, sameSize ? GL_NEAREST : GL_LINEAR);
}

void ImagePresenter::blitOnePixel(unsigned texture, int size, GLenum filter) {
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glNamedFramebufferTexture(source_.id(), GL_COLOR_ATTACHMENT0, texture, 0);
  glBlitNamedFramebuffer(source_.id(), 0, 0, 0, 1, 1, 0, 0, size, size, GL_COLOR_BUFFER_BIT,
                         filter);
}

void ImagePresenter::warmUpStretch(int width, int height) {
  if (warmedStretch_ || width <= 0 || height <= 0) return;
  const gl::Texture blank = gl::Texture::create2D(GL_RGBA8, width, height);
  blitOnePixel(blank.id(), 2, GL_LINEAR);
  glNamedFramebufferTexture(source_.id(), GL_COLOR_ATTACHMENT0, 0, 0);  // before it goes
  warmedStretch_ = true;
}

void ImagePresenter::warmUpExactCopy(unsigned texture) {
  if (warmedExactCopy_ || texture == 0) return;
  blitOnePixel(texture, 1, GL_NEAREST);
  warmedExactCopy_ = true;
}

}  // namespace ewa
