// ImagePresenter: copies the renderer's output texture to the window's default framebuffer.
#include "ui/image_presenter.h"

#include "gl/gl_api.h"

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
  if (!sameSize && !warmedExactCopy_) {
    // The window's first pictures are coarse ones, stretched; the exact copy's first use would
    // fall on the frame that shows full quality (llvmpipe compiles a blit shader per filter and
    // formats at its first draw: 35-45 ms, more than the rest of that frame). One pixel copied
    // now, with the filter the full picture will use, is drawn over by the stretch below.
    glBlitNamedFramebuffer(source_.id(), 0, 0, 0, 1, 1, 0, 0, 1, 1, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
    warmedExactCopy_ = true;
  }
  glBlitNamedFramebuffer(source_.id(), 0, 0, 0, texWidth, texHeight, 0, 0, fbWidth, fbHeight,
                         GL_COLOR_BUFFER_BIT, sameSize ? GL_NEAREST : GL_LINEAR);
}

}  // namespace ewa
