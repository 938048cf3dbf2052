// RenderTargets: creation of the slab, accumulation and output framebuffers.
#include "render/render_targets.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/stopwatch.h"
#include "gl/gl_error.h"

namespace ewa {

namespace {

// Bytes a pixel of each format the images use. Slab images are half floats where asked: a
// slab's sums are small (weights of the kernels one slab holds and normalized values), and
// blending half the bytes is what costs on a GPU.
size_t bytesPerPixel(GLenum format) {
  switch (format) {
    case GL_RGBA32F:
      return 16;
    case GL_RGBA16F:
      return 8;
    default:
      return 4;  // RGBA8, DEPTH24_STENCIL8
  }
}

// Say which limit a too-large image breaks, before GL fails with a bare error code.
void checkImageLimits(int w, int h) {
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
}

// One image of the frame's size.
gl::Texture makeImage(GLenum format, GLenum filter, int w, int h) {
  gl::Texture t = gl::Texture::create2D(format, w, h);
  t.setFilter(filter, filter);
  return t;
}

// `layout` as the images are made: back halves only with paired slabs.
TargetLayout normalized(TargetLayout layout) {
  layout.quarters = layout.quarters && layout.pairedSlabs;
  return layout;
}

}  // namespace

bool RenderTargets::ready(const TargetLayout& want) const {
  return layout_.width > 0 && layout_ == normalized(want);
}

void RenderTargets::resize(int w, int h, bool paired, bool quarter, bool normals, bool half,
                           bool coarse) {
  prepare(TargetLayout{w, h, paired, quarter, normals, half, coarse},
          std::numeric_limits<double>::infinity());
}

bool RenderTargets::prepare(const TargetLayout& want, double budgetMs,
                            platform::UploadContext* uploads) {
  const auto start = std::chrono::steady_clock::now();
  imagesMade_ = 0;
  if (ready(want)) return true;
  const TargetLayout l = normalized(want);
  if (imageJob_ && !(imageJob_->layout == l)) imageJob_.reset();  // made for another layout
  if (!(l.width == width && l.height == height && l.halfSlabs == halfSlabs_)) {
    checkImageLimits(l.width, l.height);
    // The last finished picture stays shown until a frame finishes in the new images.
    gl::Texture kept = std::move(outputDone_ ? output : previousOutput_);
    const int keptWidth = outputDone_ ? width : previousWidth_;
    const int keptHeight = outputDone_ ? height : previousHeight_;
    const double pace = msPerByte_;
    *this = RenderTargets();  // free the old images first: the new ones may be large
    msPerByte_ = pace;
    previousOutput_ = std::move(kept);
    previousWidth_ = keptWidth;
    previousHeight_ = keptHeight;
    width = l.width;
    height = l.height;
    halfSlabs_ = l.halfSlabs;
  }
  // The framebuffers are made again once every image is there; images no longer wanted go now.
  layout_ = TargetLayout{};
  for (gl::Framebuffer* f :
       {&accumFbo, &outputFbo, &slabFbo, &slabOtherFbo, &slabCoarseFbo, &slabOtherCoarseFbo})
    *f = gl::Framebuffer();
  if (!l.normalSums) slabNormal = gl::Texture();
  if (!l.pairedSlabs) slabOther = gl::Texture();
  if (!l.quarters) {
    slabBack = gl::Texture();
    slabOtherBack = gl::Texture();
  }
  if (!l.coarseSlabs) coarseMarks = gl::Texture();

  const std::vector<MissingImage> missing = missingImages(l);
  // A job under way is finished (a whole frame waits for it); a stepped frame starts one.
  if (imageJob_ || (uploads && std::isfinite(budgetMs) && !missing.empty())) {
    if (!makeOnWorker(l, missing, uploads, budgetMs - millisecondsSince(start))) return false;
  } else {
    for (const MissingImage& image : missing) {
      const double bytes = double(width) * double(height) * double(bytesPerPixel(image.format));
      // Twice the slowest pace seen: fresh memory's price varies (on llvmpipe the same images
      // cost many times more or less, as freed memory is reused or not).
      if (imagesMade_ > 0 && millisecondsSince(start) + 2.0 * msPerByte_ * bytes > budgetMs)
        return false;
      const auto made = std::chrono::steady_clock::now();
      *image.slot = makeImage(image.format, image.filter, width, height);
      gl::checkGlError("render targets");  // GL_OUT_OF_MEMORY for images too large to allocate
      msPerByte_ = std::max(msPerByte_, millisecondsSince(made) / bytes);
      ++imagesMade_;
    }
  }
  makeFramebuffers();
  layout_ = l;
  return true;
}

std::vector<RenderTargets::MissingImage> RenderTargets::missingImages(const TargetLayout& l) {
  const GLenum slabFormat = l.halfSlabs ? GL_RGBA16F : GL_RGBA32F;
  std::vector<MissingImage> images = {{&slab, slabFormat, GL_LINEAR},
                                      {&accum, GL_RGBA32F, GL_NEAREST},
                                      {&output, GL_RGBA8, GL_NEAREST},
                                      {&stencil, GL_DEPTH24_STENCIL8, GL_LINEAR}};
  if (l.normalSums) images.push_back({&slabNormal, GL_RGBA16F, GL_LINEAR});
  if (l.pairedSlabs) images.push_back({&slabOther, slabFormat, GL_LINEAR});
  if (l.quarters) {
    images.push_back({&slabBack, slabFormat, GL_LINEAR});
    images.push_back({&slabOtherBack, slabFormat, GL_LINEAR});
  }
  if (l.coarseSlabs) images.push_back({&coarseMarks, GL_DEPTH24_STENCIL8, GL_LINEAR});
  std::vector<MissingImage> missing;
  for (const MissingImage& image : images)
    if (!*image.slot) missing.push_back(image);
  return missing;
}

bool RenderTargets::makeOnWorker(const TargetLayout& l, const std::vector<MissingImage>& missing,
                                 platform::UploadContext* uploads, double waitMs) {
  if (!imageJob_) {
    imageJob_ = std::make_unique<ImageJob>();
    imageJob_->layout = l;
    std::vector<std::pair<GLenum, GLenum>> kinds;
    for (const MissingImage& image : missing) {
      imageJob_->slots.push_back(image.slot);
      kinds.emplace_back(image.format, image.filter);
    }
    imageJob_->images = std::async(std::launch::async, [uploads, kinds, w = width, h = height] {
      const platform::UploadBinding bound(*uploads);
      std::vector<gl::Texture> made;
      for (const auto& [format, filter] : kinds) {
        made.push_back(makeImage(format, filter, w, h));
        gl::checkGlError("render targets");  // GL_OUT_OF_MEMORY for images too large
      }
      glFinish();  // all there before the drawing context uses them
      return made;
    });
  }
  // Waits at most what the step has left (a step that returned at once would have the window
  // spin through empty UI frames meanwhile).
  if (!std::isfinite(waitMs)) {
    imageJob_->images.wait();
  } else {
    const auto wait = std::chrono::duration<double, std::milli>(std::max(0.0, waitMs));
    if (imageJob_->images.wait_for(wait) != std::future_status::ready) return false;
  }
  const std::unique_ptr<ImageJob> job = std::move(imageJob_);
  std::vector<gl::Texture> made = job->images.get();  // rethrows the worker's GlError
  for (size_t i = 0; i < made.size(); ++i) *job->slots[i] = std::move(made[i]);
  imagesMade_ = int(made.size());
  return true;
}

void RenderTargets::beginOutput() {
  if (!outputDone_) return;  // not shown: drawn into as it is
  gl::Texture next = std::move(spareOutput_);
  if (!next) next = makeImage(GL_RGBA8, GL_NEAREST, width, height);
  previousOutput_ = std::move(output);
  previousWidth_ = width;
  previousHeight_ = height;
  output = std::move(next);
  makeOutputFramebuffer();
  outputDone_ = false;
  outputSwapped_ = true;
}

void RenderTargets::outputFinished() {
  outputDone_ = true;
  // The picture before becomes the next banded pass's image where beginOutput swapped it out
  // (a picture of a size or layout before is freed: whole frames need no spare).
  if (outputSwapped_) spareOutput_ = std::move(previousOutput_);
  outputSwapped_ = false;
  previousOutput_ = gl::Texture();
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

void RenderTargets::makeOutputFramebuffer() {
  outputFbo = gl::Framebuffer::create();
  outputFbo.attachColor(0, output);
  outputFbo.checkComplete();
}

void RenderTargets::makeFramebuffers() {
  accumFbo = gl::Framebuffer::create();
  accumFbo.attachColor(0, accum);
  accumFbo.attachDepth(stencil, GL_DEPTH_STENCIL_ATTACHMENT);
  accumFbo.checkComplete();
  makeOutputFramebuffer();
  slabFbo = slabFramebuffer(slab, slabBack, stencil);
  if (slabOther) slabOtherFbo = slabFramebuffer(slabOther, slabOtherBack, stencil);
  if (coarseMarks) {
    slabCoarseFbo = slabFramebuffer(slab, slabBack, coarseMarks);
    if (slabOther) slabOtherCoarseFbo = slabFramebuffer(slabOther, slabOtherBack, coarseMarks);
  }
  gl::checkGlError("slab images");
}

}  // namespace ewa
