// Texture: creation, storage, upload, read-back and parameters of GL textures.
#include "gl/texture.h"

#include <string>
#include <utility>

#include "gl/gl_error.h"

namespace ewa::gl {

Texture Texture::create(GLenum target) {
  Texture texture;
  glCreateTextures(target, 1, &texture.id_);
  if (texture.id_ == 0) throw GlError("Texture::create: glCreateTextures failed");
  texture.target_ = target;
  return texture;
}

Texture Texture::create1D(GLenum internalFormat, GLsizei width, GLsizei levels) {
  Texture texture = create(GL_TEXTURE_1D);
  texture.storage1D(levels, internalFormat, width);
  texture.setFilter(GL_LINEAR, GL_LINEAR);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  return texture;
}

Texture Texture::create2D(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei levels) {
  Texture texture = create(GL_TEXTURE_2D);
  texture.storage2D(levels, internalFormat, width, height);
  texture.setFilter(GL_LINEAR, GL_LINEAR);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  return texture;
}

Texture Texture::create3D(GLenum internalFormat, GLsizei width, GLsizei height, GLsizei depth,
                          GLsizei levels) {
  Texture texture = create(GL_TEXTURE_3D);
  texture.storage3D(levels, internalFormat, width, height, depth);
  texture.setFilter(GL_LINEAR, GL_LINEAR);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  return texture;
}

Texture::~Texture() {
  release();
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      target_(std::exchange(other.target_, 0)),
      internalFormat_(std::exchange(other.internalFormat_, 0)),
      width_(std::exchange(other.width_, 0)),
      height_(std::exchange(other.height_, 0)),
      depth_(std::exchange(other.depth_, 0)),
      levels_(std::exchange(other.levels_, 0)) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, 0);
    target_ = std::exchange(other.target_, 0);
    internalFormat_ = std::exchange(other.internalFormat_, 0);
    width_ = std::exchange(other.width_, 0);
    height_ = std::exchange(other.height_, 0);
    depth_ = std::exchange(other.depth_, 0);
    levels_ = std::exchange(other.levels_, 0);
  }
  return *this;
}

void Texture::requireStorageFree(const char* what) const {
  // Immutable storage can be set once; a second call would only raise GL_INVALID_OPERATION.
  if (id_ == 0) throw GlError(std::string("Texture::") + what + " on an empty texture");
  if (levels_ != 0) throw GlError(std::string("Texture::") + what + ": storage already set");
}

void Texture::storage1D(GLsizei levels, GLenum internalFormat, GLsizei width) {
  requireStorageFree("storage1D");
  glTextureStorage1D(id_, levels, internalFormat, width);
  checkGlError("Texture::storage1D");
  levels_ = levels, internalFormat_ = internalFormat, width_ = width, height_ = 1, depth_ = 1;
}

void Texture::storage2D(GLsizei levels, GLenum internalFormat, GLsizei width, GLsizei height) {
  requireStorageFree("storage2D");
  glTextureStorage2D(id_, levels, internalFormat, width, height);
  checkGlError("Texture::storage2D");
  levels_ = levels, internalFormat_ = internalFormat, width_ = width, height_ = height;
  depth_ = 1;
}

void Texture::storage3D(GLsizei levels, GLenum internalFormat, GLsizei width, GLsizei height,
                        GLsizei depth) {
  requireStorageFree("storage3D");
  glTextureStorage3D(id_, levels, internalFormat, width, height, depth);
  checkGlError("Texture::storage3D");
  levels_ = levels, internalFormat_ = internalFormat, width_ = width, height_ = height;
  depth_ = depth;
}

void Texture::subImage1D(GLint level, GLint x, GLsizei width, GLenum format, GLenum type,
                         const void* pixels) {
  glTextureSubImage1D(id_, level, x, width, format, type, pixels);
}

void Texture::subImage2D(GLint level, GLint x, GLint y, GLsizei width, GLsizei height,
                         GLenum format, GLenum type, const void* pixels) {
  glTextureSubImage2D(id_, level, x, y, width, height, format, type, pixels);
}

void Texture::subImage3D(GLint level, GLint x, GLint y, GLint z, GLsizei width, GLsizei height,
                         GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  glTextureSubImage3D(id_, level, x, y, z, width, height, depth, format, type, pixels);
}

void Texture::getImage(GLint level, GLenum format, GLenum type, GLsizei bufferSize,
                       void* pixels) const {
  glGetTextureImage(id_, level, format, type, bufferSize, pixels);
}

void Texture::setParameter(GLenum name, GLint value) {
  glTextureParameteri(id_, name, value);
}

void Texture::setParameter(GLenum name, GLfloat value) {
  glTextureParameterf(id_, name, value);
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap) {
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  glTextureParameteri(id_, GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

void Texture::generateMipmap() {
  glGenerateTextureMipmap(id_);
}

void Texture::bindUnit(GLuint unit) const {
  glBindTextureUnit(unit, id_);
}

void Texture::release() {
  if (id_ != 0) glDeleteTextures(1, &id_);
  id_ = 0;
}

}  // namespace ewa::gl
