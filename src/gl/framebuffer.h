// Framebuffer: a move-only owner of one GL framebuffer object with texture attachments (DSA).
#pragma once

#include <vector>

#include "gl/gl_api.h"

namespace ewa::gl {

class Texture;

class Framebuffer {
 public:
  // An empty handle (id 0); no GL call.
  Framebuffer() = default;
  // Creates a framebuffer object without attachments.
  static Framebuffer create();

  ~Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // Attaches `level` of `texture` as GL_COLOR_ATTACHMENT0 + index and makes the draw buffers
  // list every attached colour index, so fragment output `index` lands in that texture.
  // The framebuffer does not own the texture, which must outlive its use here.
  void attachColor(GLuint index, const Texture& texture, GLint level = 0);
  // Attaches a depth (or depth-stencil) texture: GL_DEPTH_ATTACHMENT and the like.
  void attachDepth(const Texture& texture, GLenum attachment = GL_DEPTH_ATTACHMENT,
                   GLint level = 0);

  // glCheckNamedFramebufferStatus for the draw target.
  GLenum status() const;
  // Throws GlError "Framebuffer incomplete: GL_FRAMEBUFFER_INCOMPLETE_..." unless complete.
  void checkComplete() const;

  // Clears colour attachment `index` of this framebuffer to `rgba` (4 floats).
  void clearColor(GLint index, const GLfloat* rgba);
  // Fragment outputs reach only the attached colour buffers whose bit is set in `mask` (bit i:
  // attachment i; the others take GL_NONE); ~0u restores them all.
  void drawTo(unsigned mask);
  void clearDepth(GLfloat depth = 1.0f);
  // Binds as GL_FRAMEBUFFER.
  void bind() const;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void release();

  GLuint id_ = 0;
  std::vector<GLenum> drawBuffers_;
};

}  // namespace ewa::gl
