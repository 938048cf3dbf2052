// Texture: a move-only owner of one GL texture object with immutable storage (DSA calls).
#pragma once

#include "gl/gl_api.h"

namespace ewa::gl {

class Texture {
 public:
  // An empty handle (id 0); no GL call.
  Texture() = default;
  // Creates a texture object of `target` (GL_TEXTURE_2D, ...) without storage yet.
  static Texture create(GLenum target);
  // Shorthands: create + storage, with linear filtering and clamp-to-edge wrapping.
  static Texture create1D(GLenum internalFormat, GLsizei width, GLsizei levels = 1);
  static Texture create2D(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei levels = 1);
  static Texture create3D(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei depth,
                          GLsizei levels = 1);

  ~Texture();
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  // Allocates immutable storage; once per texture, matching its target's dimensionality.
  void storage1D(GLsizei levels, GLenum internalFormat, GLsizei width);
  void storage2D(GLsizei levels, GLenum internalFormat, GLsizei width, GLsizei height);
  void storage3D(GLsizei levels, GLenum internalFormat, GLsizei width, GLsizei height,
                 GLsizei depth);

  // Uploads a region of one level; `format`/`type` describe `pixels` (e.g. GL_RGBA, GL_FLOAT).
  void subImage1D(GLint level, GLint x, GLsizei width, GLenum format, GLenum type,
                  const void* pixels);
  void subImage2D(GLint level, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                  GLenum type, const void* pixels);
  void subImage3D(GLint level, GLint x, GLint y, GLint z, GLsizei width, GLsizei height,
                  GLsizei depth, GLenum format, GLenum type, const void* pixels);
  // Reads a whole level back into `pixels`, which holds `bufferSize` bytes.
  void getImage(GLint level, GLenum format, GLenum type, GLsizei bufferSize, void* pixels) const;

  void setParameter(GLenum name, GLint value);
  void setParameter(GLenum name, GLfloat value);
  // GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER.
  void setFilter(GLenum minFilter, GLenum magFilter);
  // GL_TEXTURE_WRAP_S/T/R alike.
  void setWrap(GLenum wrap);
  void generateMipmap();
  // Binds to texture unit `unit` for sampling (glBindTextureUnit).
  void bindUnit(GLuint unit) const;

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  GLenum internalFormat() const { return internalFormat_; }
  GLsizei width() const { return width_; }
  GLsizei height() const { return height_; }
  GLsizei depth() const { return depth_; }
  GLsizei levels() const { return levels_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void release();
  void requireStorageFree(const char* what) const;

  GLuint id_ = 0;
  GLenum target_ = 0;
  GLenum internalFormat_ = 0;
  GLsizei width_ = 0, height_ = 0, depth_ = 0, levels_ = 0;
};

}  // namespace ewa::gl
