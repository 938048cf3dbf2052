// TileEwaPrograms: the compute EWA splatter's programs, compiled on first use; renderers that
// share a SplatProgramSet (the window's levels of detail) share one set of them.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "gl/program.h"
#include "gl/shader_library.h"

namespace ewa {

class TileEwaPrograms {
 public:
  // `tileSize`: pixels a side of a tile (one work group), 8 or 16. Compiles nothing yet.
  TileEwaPrograms(const gl::ShaderLibrary& shaders, int tileSize);

  int tileSize() const { return tileSize_; }
  // The binning passes of shaders/tile_ewa.comp.glsl over the CPU's entries or, gpuOrder, the
  // GPU partition's lists; the bucket scan of shaders/tile_splat.comp.glsl.
  gl::Program& count(bool gpuOrder);
  gl::Program& scatter(bool gpuOrder);
  gl::Program& scan();
  // The composite: pre-classified (shaders/tile_ewa.comp.glsl), or post-classified, unshaded or
  // shaded from the field or, rayNormals, from the gradient texture
  // (shaders/tile_ewa_post.comp.glsl).
  gl::Program& composite(bool post, bool shading, bool rayNormals);
  // The footprint records' pass (shaders/tile_ewa_footprints.comp.glsl) for a splat variant:
  // its key and #define lines (SplatVariant).
  gl::Program& footprints(unsigned variantKey, const std::string& variantDefines);
  // Programs compiled so far (a renderer sharing the set compiles none another compiled).
  size_t compiled() const { return compiled_; }

 private:
  gl::Program& once(std::optional<gl::Program>& slot, const std::string& file,
                    const std::string& defines);

  gl::ShaderLibrary shaders_;  // a copy: the set may outlive the renderer that made it
  int tileSize_;
  std::optional<gl::Program> count_[2], scatter_[2], scan_, composite_[4];
  std::map<unsigned, gl::Program> footprints_;
  size_t compiled_ = 0;
};

}  // namespace ewa
