// TileEwaPrograms: each pass's program compiled the first time a draw asks for it.
#include "render/tile_ewa_programs.h"

#include <utility>

namespace ewa {

namespace {

std::string tileSizeDefine(int tileSize) {
  return "#define TILE_SIZE " + std::to_string(tileSize) + "\n";
}

std::string defines(int tileSize, const char* pass) {
  return tileSizeDefine(tileSize) + "#define " + pass + " 1\n";
}

const char* const kGpuOrder = "#define GPU_ORDER 1\n";

}  // namespace

TileEwaPrograms::TileEwaPrograms(const gl::ShaderLibrary& shaders, int tileSize)
    : shaders_(shaders), tileSize_(tileSize) {}

gl::Program& TileEwaPrograms::once(std::optional<gl::Program>& slot, const std::string& file,
                                   const std::string& text) {
  if (!slot) {
    slot = shaders_.computeProgram(file, text);
    ++compiled_;
  }
  return *slot;
}

gl::Program& TileEwaPrograms::count(bool gpuOrder) {
  return once(count_[gpuOrder], "tile_ewa.comp.glsl",
              (gpuOrder ? kGpuOrder : "") + defines(tileSize_, "COUNT_PASS"));
}

gl::Program& TileEwaPrograms::scatter(bool gpuOrder) {
  return once(scatter_[gpuOrder], "tile_ewa.comp.glsl",
              (gpuOrder ? kGpuOrder : "") + defines(tileSize_, "SCATTER_PASS"));
}

gl::Program& TileEwaPrograms::scan() {
  // The scan of tile_splat.comp.glsl, over (tile, slab) buckets in place of tiles.
  return once(scan_, "tile_splat.comp.glsl",
              defines(tileSize_, "SCAN_PASS") + "#define IMAGE_FORMAT rgba32f\n");
}

gl::Program& TileEwaPrograms::composite(bool post, bool shading, bool rayNormals) {
  if (!post) return once(composite_[0], "tile_ewa.comp.glsl", defines(tileSize_, "COMPOSITE_PASS"));
  const bool ray = shading && rayNormals, field = shading && !rayNormals;
  auto flag = [](bool on) { return on ? "1" : "0"; };
  return once(composite_[!shading ? 1
                         : ray    ? 3
                                  : 2],
              "tile_ewa_post.comp.glsl",
              tileSizeDefine(tileSize_) + "#define SLAB_SHADING " + flag(shading) +
                  "\n#define SLAB_FIELD_NORMALS " + flag(field) + "\n#define SLAB_RAY_NORMALS " +
                  flag(ray) + "\n");
}

gl::Program& TileEwaPrograms::footprints(unsigned variantKey, const std::string& variantDefines) {
  auto it = footprints_.find(variantKey);
  if (it == footprints_.end()) {
    it = footprints_
             .emplace(variantKey,
                      shaders_.computeProgram("tile_ewa_footprints.comp.glsl", variantDefines))
             .first;
    ++compiled_;
  }
  return it->second;
}

}  // namespace ewa
