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
// sees all of it once it binds the buffer), or GlError.
GLuint uploadOnWorker(platform::UploadContext& context, GLsizeiptr bytes, const void* data) {
  context.bind();
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferData(id, bytes, data, GL_STATIC_DRAW);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) glDeleteBuffers(1, &id);
  glFinish();
  context.release();
  if (error != GL_NO_ERROR)
    throw gl::GlError("splat buffer upload (" + std::to_string(bytes) + " bytes): GL error " +
                      std::to_string(error));
  return id;
}

}  // namespace

SplatUpload::SplatUpload(ClassifiedSplats splats, const Classification& classification,
                         platform::UploadContext& context)
    : splats_(std::move(splats)), classification_(classification) {
  const auto& records = splats_.splats.splats();
  bytes_ = GLsizeiptr(std::max<size_t>(1, records.size()) * sizeof(PackedSplat));
  const void* data = records.empty() ? nullptr : records.data();
  upload_ = std::async(std::launch::async, [&context, bytes = bytes_, data] {
    return uploadOnWorker(context, bytes, data);
  });
}

SplatUpload::~SplatUpload() {
  if (!upload_.valid()) return;
  try {
    // Not taken: deleted through the drawing context, bound here (one share group).
    gl::Buffer::adopt(upload_.get(), bytes_);
  } catch (const std::exception&) {
    // Its error is about a set nobody will draw.
  }
}

bool SplatUpload::done() const {
  return !upload_.valid() || upload_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

void SplatUpload::finish(ClassifiedSplats* splats, gl::Buffer* buffer) {
  const GLuint id = upload_.get();
  *buffer = gl::Buffer::adopt(id, bytes_);
  *splats = std::move(splats_);
}

}  // namespace ewa
