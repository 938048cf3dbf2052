// ImagePresenter: copies the renderer's output texture to the window's default framebuffer.
#pragma once

#include "gl/framebuffer.h"

namespace ewa {

class ImagePresenter {
 public:
  // Creates the read framebuffer; the window's GL 4.5 context must be current.
  ImagePresenter();

  // Blits `texture` (RGBA8, texWidth x texHeight, bottom row first as GL stores it) over the
  // whole default framebuffer of fbWidth x fbHeight pixels, stretching it if the sizes differ.
  // A zero texture clears the window to black instead.
  void present(unsigned texture, int texWidth, int texHeight, int fbWidth, int fbHeight);

 private:
  gl::Framebuffer source_;        // wraps the texture as a blit source
  bool warmedExactCopy_ = false;  // the same-size blit has been drawn once
};

}  // namespace ewa
