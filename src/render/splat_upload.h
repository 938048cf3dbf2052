// SplatUpload: a splat set uploaded into a new GL buffer by a worker thread through a context
// sharing the renderer's, so that a big set does not hold the thread that draws.
#pragma once

#include <future>

#include "core/splat_attributes.h"
#include "gl/buffer.h"
#include "platform/upload_context.h"

namespace ewa {

// On llvmpipe a buffer's upload costs what touching its fresh memory costs: Mesa clears a new
// buffer, then copies the data in (a mid-size volume's splats take most of a UI frame, a 512^3
// volume's many frames' worth). Here a worker binds `context` (one of the same share group),
// makes the buffer and finishes it, and the drawing thread takes it over once that is done.
// Neither movable nor copyable: the worker reads this object's splats.
class SplatUpload {
 public:
  // Starts the upload of `splats` (one record at least, as the renderer's buffer). `context`
  // must outlive this object and bind to no other thread meanwhile.
  SplatUpload(ClassifiedSplats splats, const Classification& classification,
              platform::UploadContext& context);
  // Waits for the worker; a finished buffer nobody took is deleted (the drawing context bound).
  ~SplatUpload();
  SplatUpload(const SplatUpload&) = delete;
  SplatUpload& operator=(const SplatUpload&) = delete;

  // True once the worker is done (never waits).
  bool done() const;
  const Classification& classification() const { return classification_; }

  // Waits for the worker and hands over the set and its buffer. Throws what the worker threw
  // (GlError: the GL could not make the buffer, e.g. out of memory; ContextError).
  void finish(ClassifiedSplats* splats, gl::Buffer* buffer);

 private:
  ClassifiedSplats splats_;
  Classification classification_;
  std::future<gl::Buffer> upload_;
};

}  // namespace ewa
