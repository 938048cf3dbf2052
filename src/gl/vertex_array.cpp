// VertexArray: creation and attribute/buffer setup of GL vertex array objects.
#include "gl/vertex_array.h"

#include <utility>

#include "gl/buffer.h"
#include "gl/gl_error.h"

namespace ewa::gl {

VertexArray VertexArray::create() {
  VertexArray array;
  glCreateVertexArrays(1, &array.id_);
  if (array.id_ == 0) throw GlError("VertexArray::create: glCreateVertexArrays failed");
  return array;
}

VertexArray::~VertexArray() {
  release();
}

VertexArray::VertexArray(VertexArray&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

void VertexArray::setAttribute(GLuint attribute, GLuint binding, GLint components, GLenum type,
                               GLuint relativeOffset, bool normalized) {
  glEnableVertexArrayAttrib(id_, attribute);
  glVertexArrayAttribFormat(id_, attribute, components, type, normalized ? GL_TRUE : GL_FALSE,
                            relativeOffset);
  glVertexArrayAttribBinding(id_, attribute, binding);
}

void VertexArray::setIntegerAttribute(GLuint attribute, GLuint binding, GLint components,
                                      GLenum type, GLuint relativeOffset) {
  glEnableVertexArrayAttrib(id_, attribute);
  glVertexArrayAttribIFormat(id_, attribute, components, type, relativeOffset);
  glVertexArrayAttribBinding(id_, attribute, binding);
}

void VertexArray::setVertexBuffer(GLuint binding, const Buffer& buffer, GLintptr offset,
                                  GLsizei stride, GLuint divisor) {
  glVertexArrayVertexBuffer(id_, binding, buffer.id(), offset, stride);
  glVertexArrayBindingDivisor(id_, binding, divisor);
}

void VertexArray::setElementBuffer(const Buffer& buffer) {
  glVertexArrayElementBuffer(id_, buffer.id());
}

void VertexArray::bind() const {
  glBindVertexArray(id_);
}

void VertexArray::release() {
  if (id_ != 0) glDeleteVertexArrays(1, &id_);
  id_ = 0;
}

}  // namespace ewa::gl
