// VertexArray: a move-only owner of one GL vertex array object, set up through DSA calls.
#pragma once

#include "gl/gl_api.h"

namespace ewa::gl {

class Buffer;

class VertexArray {
 public:
  // An empty handle (id 0); no GL call.
  VertexArray() = default;
  // Creates a VAO. The core profile needs one bound for any draw, even without attributes.
  static VertexArray create();

  ~VertexArray();
  VertexArray(VertexArray&& other) noexcept;
  VertexArray& operator=(VertexArray&& other) noexcept;
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;

  // Float attribute `attribute` reads `components` values of `type` at `relativeOffset` in
  // the vertices of buffer binding `binding`; enables the attribute.
  void setAttribute(GLuint attribute, GLuint binding, GLint components, GLenum type,
                    GLuint relativeOffset, bool normalized = false);
  // Integer attribute (glVertexArrayAttribIFormat); enables the attribute.
  void setIntegerAttribute(GLuint attribute, GLuint binding, GLint components, GLenum type,
                           GLuint relativeOffset);
  // Feeds buffer binding `binding` from `buffer`; `divisor` 1 makes it per instance.
  void setVertexBuffer(GLuint binding, const Buffer& buffer, GLintptr offset, GLsizei stride,
                       GLuint divisor = 0);
  void setElementBuffer(const Buffer& buffer);
  // Binds for drawing.
  void bind() const;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void release();

  GLuint id_ = 0;
};

}  // namespace ewa::gl
