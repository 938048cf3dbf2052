// SplatUpload: the worker's buffer in the upload context, and its hand-over.
#include "render/splat_upload.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "gl/gl_error.h"

namespace ewa {

namespace {

// On the worker, `context` bound: a buffer holding `data`, finished (so the drawing context
// sees all of it once it binds the buffer), or GlError (GL_OUT_OF_MEMORY: deleted here).
gl::Buffer uploadOnWorker(platform::UploadContext& context, GLsizeiptr bytes, const void* data) {
  const platform::UploadBinding bound(context);
  gl::Buffer buffer = gl::Buffer::create(bytes, data, GL_STATIC_DRAW);
  gl::checkGlError(("splat buffer upload (" + std::to_string(bytes) + " bytes)").c_str());
  glFinish();
  return buffer;
}

}  // namespace

SplatUpload::SplatUpload(ClassifiedSplats splats, const Classification& classification,
                         platform::UploadContext& context)
    : splats_(std::move(splats)), classification_(classification) {
  const auto& records = splats_.splats.splats();
  const auto bytes = GLsizeiptr(std::max<size_t>(1, records.size()) * sizeof(PackedSplat));
  const void* data = records.empty() ? nullptr : records.data();
  upload_ = std::async(std::launch::async,
                       [&context, bytes, data] { return uploadOnWorker(context, bytes, data); });
}

SplatUpload::~SplatUpload() {
  if (!upload_.valid()) return;
  try {
    upload_.get();  // not taken: deleted through the drawing context, bound here (one share group)
  } catch (const std::exception&) {
    // Its error is about a set nobody will draw.
  }
}

bool SplatUpload::done() const {
  return !upload_.valid() || upload_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

void SplatUpload::finish(ClassifiedSplats* splats, gl::Buffer* buffer) {
  *buffer = upload_.get();
  *splats = std::move(splats_);
}

}  // namespace ewa
