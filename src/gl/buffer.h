// Buffer: a move-only owner of one GL buffer object, created and filled through DSA calls.
#pragma once

#include "gl/gl_api.h"

namespace ewa::gl {

class Buffer {
 public:
  // An empty handle (id 0); no GL call, so it can be a member set up later.
  Buffer() = default;
  // Creates a buffer of `size` bytes, initialised from `data` when it is not null.
  static Buffer create(GLsizeiptr size, const void* data = nullptr, GLenum usage = GL_DYNAMIC_DRAW);

  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // Reallocates the store (glNamedBufferData); creates the buffer first when empty.
  void setData(GLsizeiptr size, const void* data, GLenum usage = GL_DYNAMIC_DRAW);
  // Makes the store hold at least `size` bytes (16 at least), its contents not kept: exactly
  // that the first time (a 512^3 volume's per-splat buffers are gigabytes), half again more
  // when it grows, so that a size that creeps up (views turning) settles. A failed allocation
  // (GL_OUT_OF_MEMORY) throws GlError naming `what`.
  void reserve(GLsizeiptr size, const char* what);
  // Overwrites bytes [offset, offset + size); throws GlError when outside the store.
  void setSubData(GLintptr offset, GLsizeiptr size, const void* data);
  // Copies bytes [offset, offset + size) into `out`; throws GlError when outside the store.
  void getSubData(GLintptr offset, GLsizeiptr size, void* out) const;
  // Binds to an indexed target (GL_SHADER_STORAGE_BUFFER, GL_UNIFORM_BUFFER, ...).
  void bindBase(GLenum target, GLuint index) const;

  GLuint id() const { return id_; }
  GLsizeiptr size() const { return size_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void release();

  GLuint id_ = 0;
  GLsizeiptr size_ = 0;
};

}  // namespace ewa::gl
