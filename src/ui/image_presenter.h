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
  // Copies one pixel of `texture` to the default framebuffer the way a same-size present does,
  // once: the window's first pictures are coarse ones, stretched, and the exact copy's first
  // use would fall on the frame that shows full quality (llvmpipe compiles a blit shader per
  // filter and formats at its first draw, which costs more than the rest of that frame). Called
  // in a UI frame that does not present, after one that did (the pixel is drawn over by the
  // next present before any swap).
  void warmUpExactCopy(unsigned texture);
  // Stretches one pixel of a blank RGBA8 image of width x height to the default framebuffer,
  // once: llvmpipe compiles the blit of an image of a size new to it at its first draw (55-80
  // ms; its sampler code depends on the sides), so a frame before the window's first picture
  // takes that off the picture's own present. Drawn over by the next present.
  void warmUpStretch(int width, int height);
  bool stretchWarmedUp() const { return warmedStretch_; }

 private:
  // One pixel of `texture` to a size x size square at the default framebuffer's corner, the
  // blit a present of that filter draws (compiled by llvmpipe at its first draw).
  void blitOnePixel(unsigned texture, int size, GLenum filter);
  gl::Framebuffer source_;        // wraps the texture as a blit source
  bool warmedExactCopy_ = false;  // the same-size blit has been drawn (or warmed up) once
  bool warmedStretch_ = false;
};

}  // namespace ewa
