// Framebuffer: attachments, completeness check and clears of GL framebuffer objects.
#include "gl/framebuffer.h"

#include <algorithm>
#include <utility>

#include "gl/gl_error.h"
#include "gl/texture.h"

namespace ewa::gl {

Framebuffer Framebuffer::create() {
  Framebuffer framebuffer;
  glCreateFramebuffers(1, &framebuffer.id_);
  if (framebuffer.id_ == 0) throw GlError("Framebuffer::create: glCreateFramebuffers failed");
  return framebuffer;
}

Framebuffer::~Framebuffer() {
  release();
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)), drawBuffers_(std::move(other.drawBuffers_)) {
  other.drawBuffers_.clear();
}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, 0);
    drawBuffers_ = std::move(other.drawBuffers_);
    other.drawBuffers_.clear();
  }
  return *this;
}

void Framebuffer::attachColor(GLuint index, const Texture& texture, GLint level) {
  if (id_ == 0) throw GlError("Framebuffer::attachColor on an empty framebuffer");
  GLenum attachment = GL_COLOR_ATTACHMENT0 + index;
  glNamedFramebufferTexture(id_, attachment, texture.id(), level);
  if (std::find(drawBuffers_.begin(), drawBuffers_.end(), attachment) == drawBuffers_.end()) {
    drawBuffers_.push_back(attachment);
    std::sort(drawBuffers_.begin(), drawBuffers_.end());
  }
  drawTo(~0u);
  glNamedFramebufferReadBuffer(id_, drawBuffers_.front());
}

void Framebuffer::drawTo(unsigned mask) {
  if (drawBuffers_.empty()) return;
  // glDrawBuffers maps fragment output i to entry i, so leave gaps as GL_NONE.
  std::vector<GLenum> mapping(drawBuffers_.back() - GL_COLOR_ATTACHMENT0 + 1, GL_NONE);
  for (GLenum buffer : drawBuffers_) {
    const unsigned index = buffer - GL_COLOR_ATTACHMENT0;
    if (index < 32 && (mask >> index) & 1u) mapping[index] = buffer;
  }
  glNamedFramebufferDrawBuffers(id_, static_cast<GLsizei>(mapping.size()), mapping.data());
}

void Framebuffer::attachDepth(const Texture& texture, GLenum attachment, GLint level) {
  if (id_ == 0) throw GlError("Framebuffer::attachDepth on an empty framebuffer");
  glNamedFramebufferTexture(id_, attachment, texture.id(), level);
}

GLenum Framebuffer::status() const {
  return glCheckNamedFramebufferStatus(id_, GL_DRAW_FRAMEBUFFER);
}

void Framebuffer::checkComplete() const {
  if (id_ == 0) throw GlError("Framebuffer incomplete: empty framebuffer object");
  GLenum result = status();
  if (result != GL_FRAMEBUFFER_COMPLETE) {
    throw GlError("Framebuffer incomplete: " + framebufferStatusString(result));
  }
}

void Framebuffer::clearColor(GLint index, const GLfloat* rgba) {
  glClearNamedFramebufferfv(id_, GL_COLOR, index, rgba);
}

void Framebuffer::clearDepth(GLfloat depth) {
  glClearNamedFramebufferfv(id_, GL_DEPTH, 0, &depth);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
}

void Framebuffer::release() {
  if (id_ != 0) glDeleteFramebuffers(1, &id_);
  id_ = 0;
  drawBuffers_.clear();
}

}  // namespace ewa::gl
