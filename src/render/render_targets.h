// RenderTargets: the slab, accumulation, stencil and 8-bit output images of one viewport size.
#pragma once

#include <cstddef>
#include <future>
#include <memory>
#include <vector>

#include "gl/framebuffer.h"
#include "gl/texture.h"
#include "platform/upload_context.h"

namespace ewa {

// The images one frame needs: their size and which of the optional ones (RenderTargets::resize).
struct TargetLayout {
  int width = 0;
  int height = 0;
  bool pairedSlabs = false;
  bool quarters = false;  // only with paired slabs
  bool normalSums = false;
  bool halfSlabs = false;
  bool coarseSlabs = false;
  bool operator==(const TargetLayout& o) const {
    return width == o.width && height == o.height && pairedSlabs == o.pairedSlabs &&
           quarters == o.quarters && normalSums == o.normalSums && halfSlabs == o.halfSlabs &&
           coarseSlabs == o.coarseSlabs;
  }
};

struct RenderTargets {
  int width = 0;
  int height = 0;
  // RGBA16F or RGBA32F (halfSlabs()): (sum of colour * optical depth, sum of optical depth)
  gl::Texture slab;
  // RGBA16F, post-classified with voxel normals: sum of weight * normal (colour attachment 1 of
  // the slab framebuffers). Absent otherwise: a slab framebuffer's draw buffers are its
  // attachments (gl::Framebuffer::attachColor), so the splats write it and the back halves only
  // where they are used.
  gl::Texture slabNormal;
  gl::Texture accum;    // RGBA32F: premultiplied colour and opacity, front to back
  gl::Texture output;   // RGBA8: the final picture over the background
  gl::Texture stencil;  // DEPTH24_STENCIL8, shared by slab and accumulation: opaque pixels
  gl::Framebuffer slabFbo;
  gl::Framebuffer accumFbo;
  gl::Framebuffer outputFbo;
  // Pre-integration between slabs: a second slab image, so that consecutive slabs alternate
  // between the two and the slab pass reads the one before (same normal and stencil images).
  gl::Texture slabOther;
  gl::Framebuffer slabOtherFbo;
  // Paired slabs in quarters: each slab image's back half, (weight * value, weight) of its
  // third and fourth quarters (as `slab`, colour attachment 2); the image itself then holds the
  // first and second quarters.
  gl::Texture slabBack;
  gl::Texture slabOtherBack;
  // Coarser slab images (slab_image_scale.h): their splats' marks, at the coarser image's
  // texels (DEPTH24_STENCIL8 as `stencil`, so a blit carries them to the picture's pixels for
  // the slab pass), and each slab image's framebuffer with it in place of `stencil`.
  gl::Texture coarseMarks;
  gl::Framebuffer slabCoarseFbo;
  gl::Framebuffer slabOtherCoarseFbo;

  // (Re)creates the images when the size changes, the second slab image when `pairedSlabs`
  // asks for it, the back halves when `quarters` does and the normal sums when `normalSums`
  // does (freed when not), the coarser images' marks when `coarseSlabs` does; the slab images
  // are half floats when `halfSlabs` says so (all made again when it changes). Throws
  // gl::GlError if incomplete.
  void resize(int w, int h, bool pairedSlabs = false, bool quarters = false,
              bool normalSums = false, bool halfSlabs = false, bool coarseSlabs = false);
  // The same, an image at a time within `budgetMs` (at least one a call, the next only where its
  // bytes at twice the slowest pace seen still fit): a much larger image's first frame on a
  // software GL spends long on each image (fresh memory cleared page by page), more in all than a
  // window's UI frame may. With `uploads` (a context of this one's share group) and a finite
  // budget the missing images are made at once on a worker bound to it instead, where their fresh
  // memory is touched, and the calls wait for it at most the budget and return false until it is
  // done (the framebuffers are then made here).
  // True once every image and framebuffer is there.
  bool prepare(const TargetLayout& layout, double budgetMs,
               platform::UploadContext* uploads = nullptr);
  // Whether the images of `layout` are all there (prepare would do nothing).
  bool ready(const TargetLayout& layout) const;
  bool halfSlabs() const { return halfSlabs_; }
  bool pairedSlabs() const { return bool(slabOther); }
  bool quarters() const { return bool(slabBack); }
  bool normalSums() const { return bool(slabNormal); }
  bool coarseSlabs() const { return bool(coarseMarks); }
  // Slab image `i` (0 or 1), its back half and its framebuffer; 1 only with paired slabs.
  const gl::Texture& slabImage(int i) const { return i ? slabOther : slab; }
  const gl::Texture& slabBackImage(int i) const { return i ? slabOtherBack : slabBack; }
  gl::Framebuffer& slabTarget(int i) { return i ? slabOtherFbo : slabFbo; }
  // Its framebuffer for a coarser image (with coarseMarks); only with coarse slabs.
  gl::Framebuffer& slabCoarseTarget(int i) { return i ? slabOtherCoarseFbo : slabCoarseFbo; }
  // The picture to show and its size: the output image once a frame has finished in it, else
  // the last one finished at the size before, kept while a frame of a new size is drawn (a
  // window's refinement or capture at another size keeps its picture on screen meanwhile).
  const gl::Texture& shownOutput() const { return outputDone_ ? output : previousOutput_; }
  int shownWidth() const { return outputDone_ ? width : previousWidth_; }
  int shownHeight() const { return outputDone_ ? height : previousHeight_; }
  // Before a final pass drawn in bands over several steps: a shown output image stays shown (as
  // the picture before) and the pass draws into another one of the same size (kept from the
  // last time), so a half-drawn picture is never shown.
  void beginOutput();
  // A frame's final pass has drawn the output image: it is the one shown from now on.
  void outputFinished();
  // Images made by prepare (0 when the layout was already there), for tests and the log.
  int imagesMade() const { return imagesMade_; }
  // Bytes the images hold: one slab image (two with paired slabs, four in quarters; 8 or 16
  // bytes a pixel each), the RGBA32F accumulation, one RGBA8, one depth-stencil (4 bytes) per
  // pixel (two with coarse slabs), the RGBA16F normal sums if any, and the picture before
  // while it is kept (and its image once free, for the next banded final pass).
  size_t bytes() const {
    const size_t slabImage = halfSlabs_ ? 8 : 16;
    return size_t(width) * size_t(height) *
               (slabImage + 16 + 4 + 4 + (coarseSlabs() ? 4 : 0) + (normalSums() ? 8 : 0) +
                (pairedSlabs() ? slabImage : 0) + (quarters() ? 2 * slabImage : 0)) +
           (previousOutput_ ? size_t(previousWidth_) * size_t(previousHeight_) * 4 : 0) +
           (spareOutput_ ? size_t(width) * size_t(height) * 4 : 0);
  }

 private:
  // The framebuffer of one slab image: the image, the normal sums and its back half if any,
  // and `depth` (the stencil, or the coarser images' marks).
  gl::Framebuffer slabFramebuffer(const gl::Texture& image, const gl::Texture& back,
                                  const gl::Texture& depth);
  void makeOutputFramebuffer();
  void makeFramebuffers();
  // The missing images of `layout` in the order prepare makes them.
  struct MissingImage {
    gl::Texture* slot;
    GLenum format;
    GLenum filter;  // coarser slab images (and their marks) are read bilinearly
  };
  std::vector<MissingImage> missingImages(const TargetLayout& layout);
  // Makes `missing` on a worker bound to `uploads` (or finishes the job under way for
  // `layout`), waiting for it at most `waitMs`; true once they are in their slots.
  bool makeOnWorker(const TargetLayout& layout, const std::vector<MissingImage>& missing,
                    platform::UploadContext* uploads, double waitMs);

  bool halfSlabs_ = false;
  TargetLayout layout_;  // what the framebuffers were made for; width 0: none yet
  int imagesMade_ = 0;
  double msPerByte_ = 0.0;   // the slowest pace (ms a byte) an image was made at so far
  bool outputDone_ = false;  // a final pass has drawn `output` since it was made
  gl::Texture previousOutput_;
  int previousWidth_ = 0, previousHeight_ = 0;
  gl::Texture spareOutput_;     // an RGBA8 image of this size for beginOutput
  bool outputSwapped_ = false;  // previousOutput_ is the one beginOutput swapped out
  // Images being made on a worker for `layout`, to go into `slots` in order.
  struct ImageJob {
    TargetLayout layout;
    std::vector<gl::Texture*> slots;
    std::future<std::vector<gl::Texture>> images;
  };
  std::unique_ptr<ImageJob> imageJob_;  // waits for the worker when it goes
};

}  // namespace ewa
