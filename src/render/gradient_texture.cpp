// GradientTexture: packs the volume's gradient and uploads it as an RGB10_A2 3D texture.
#include "render/gradient_texture.h"

#include <algorithm>
#include <string>

#include "core/gradient_volume.h"
#include "gl/gl_error.h"

namespace ewa {

bool GradientTexture::sync(const Volume& volume, GradientMode mode) {
  if (texture_ && volume_ == &volume && mode_ == mode) return false;
  const auto& d = volume.dims();
  GLint largest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
  if (std::max({d[0], d[1], d[2]}) > int64_t(largest))
    throw gl::GlError("volume: " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
                      std::to_string(d[2]) + " voxels exceed GL_MAX_3D_TEXTURE_SIZE " +
                      std::to_string(largest) +
                      " for the ray normals' gradient texture (--post-normals field does not "
                      "need it)");
  release();
  const PackedGradients packed = packGradients(volume, mode);
  texture_ = gl::Texture::create3D(GL_RGB10_A2, GLsizei(d[0]), GLsizei(d[1]), GLsizei(d[2]));
  // In parts of at most 64 MB, so the driver's staging copy stays small for big volumes.
  const int64_t slice = d[0] * d[1];
  const int64_t step = std::max<int64_t>(1, (int64_t(64) << 20) / (4 * slice));
  for (int64_t z = 0; z < d[2]; z += step) {
    const int64_t n = std::min(step, d[2] - z);
    texture_.subImage3D(0, 0, 0, GLint(z), GLsizei(d[0]), GLsizei(d[1]), GLsizei(n), GL_RGBA,
                        GL_UNSIGNED_INT_2_10_10_10_REV, packed.texels.data() + z * slice);
  }
  gl::checkGlError(
      ("gradient texture upload (" + std::to_string(d[0] * d[1] * d[2]) + " voxels)").c_str());
  volume_ = &volume;
  mode_ = mode;
  return true;
}

void GradientTexture::release() {
  texture_ = gl::Texture();
  volume_ = nullptr;
}

void GradientTexture::bindUnit(unsigned unit) const {
  if (texture_) {
    texture_.bindUnit(unit);
  } else {
    glBindTextureUnit(unit, 0);
  }
}

size_t GradientTexture::bytes() const {
  return texture_
             ? size_t(texture_.width()) * size_t(texture_.height()) * size_t(texture_.depth()) * 4
             : 0;
}

}  // namespace ewa
