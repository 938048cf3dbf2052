// Buffer: creation, upload and ownership transfer of GL buffer objects.
#include "gl/buffer.h"

#include <algorithm>
#include <string>
#include <utility>

#include "gl/gl_error.h"

namespace ewa::gl {

namespace {

void checkRange(GLintptr offset, GLsizeiptr size, GLsizeiptr capacity, const char* what) {
  if (offset < 0 || size < 0 || offset + size > capacity) {
    throw GlError(std::string("Buffer::") + what + ": range [" + std::to_string(offset) + ", " +
                  std::to_string(offset + size) + ") outside the " + std::to_string(capacity) +
                  "-byte store");
  }
}

}  // namespace

Buffer Buffer::create(GLsizeiptr size, const void* data, GLenum usage) {
  Buffer buffer;
  buffer.setData(size, data, usage);
  return buffer;
}

Buffer::~Buffer() {
  release();
}

Buffer::Buffer(Buffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)), size_(std::exchange(other.size_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, 0);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void Buffer::setData(GLsizeiptr size, const void* data, GLenum usage) {
  if (size < 0) throw GlError("Buffer::setData: negative size");
  if (id_ == 0) glCreateBuffers(1, &id_);
  glNamedBufferData(id_, size, data, usage);
  size_ = size;
}

void Buffer::reserve(GLsizeiptr size, const char* what) {
  size = std::max<GLsizeiptr>(size, 16);
  if (id_ != 0 && size_ >= size) return;
  setData(id_ != 0 ? size + size / 2 : size, nullptr, GL_DYNAMIC_DRAW);
  checkGlError(what);
}

void Buffer::setSubData(GLintptr offset, GLsizeiptr size, const void* data) {
  checkRange(offset, size, size_, "setSubData");
  if (size > 0) glNamedBufferSubData(id_, offset, size, data);
}

void Buffer::getSubData(GLintptr offset, GLsizeiptr size, void* out) const {
  checkRange(offset, size, size_, "getSubData");
  if (size > 0) glGetNamedBufferSubData(id_, offset, size, out);
}

void Buffer::bindBase(GLenum target, GLuint index) const {
  glBindBufferBase(target, index, id_);
}

void Buffer::release() {
  if (id_ != 0) glDeleteBuffers(1, &id_);
  id_ = 0;
  size_ = 0;
}

}  // namespace ewa::gl
