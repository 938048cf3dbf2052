// GpuSlabPartition: the slab partition built by compute passes over the splat buffers, with
// the order list, per-slab first entries and indirect draw commands left on the GPU.
// SlabPartition (src/core) is its reference: the same slabs, each with the same splats.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/slab_partition.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"

namespace ewa {

class GpuSlabPartition {
 public:
  explicit GpuSlabPartition(const gl::ShaderLibrary& shaders);

  // SlabPartition::build on the GPU for the `count` splats in `splats` (binding 0) and
  // `attributes` (binding 2; `surfaces`: they may hold surface splats). Reads back only the
  // depth range (a few bytes, one wait for the first pass) to size the slabs, and the number of
  // entries (a second wait, for the count and scan passes) to size the order list: slabs()
  // then holds every slab between the range's ends, empty ones included, with first and count
  // unknown (0) until readCounts().
  void build(const gl::Buffer& splats, const gl::Buffer& attributes, size_t count, bool surfaces,
             const glm::dvec3& origin, const glm::dmat4& view, double thickness, double nearCull,
             const DepthExtent& extent);
  // Reads the per-slab counts and first entries back (waits for the passes) into slabs().
  void readCounts();
  bool countsKnown() const { return countsKnown_; }

  const std::vector<Slab>& slabs() const { return slabs_; }
  size_t splatCount() const { return splatCount_; }
  double nearestCenter() const { return nearestCenter_; }
  // The order list (entries as in SlabPartition::order(), slab by slab), read back (tests).
  std::vector<uint32_t> readOrder() const;

  // The order list itself (drawn through windows of it when the counts are read back), its
  // length, and each slab's first entry (slabs().size() of them).
  const gl::Buffer& orderBuffer() const { return order_; }
  size_t entryCount() const { return entryCount_; }
  const gl::Buffer& firstBuffer() const { return first_; }
  // Binds the order list (binding 1), the first entries (binding 3) and the draw commands
  // (GL_DRAW_INDIRECT_BUFFER) for drawing.
  void bindForDrawing() const;
  // Byte offsets in the command buffer of slab `slab`'s point and quad draws.
  size_t pointCommand(size_t slab) const { return slab * 16; }
  size_t quadCommand(size_t slab) const { return (slabs_.size() + slab) * 16; }
  // Bytes of the buffers it allocated.
  size_t bytes() const;

 private:
  gl::Program extentPass_, countPass_, scanPass_, scatterPass_;
  gl::Buffer range_, cursor_, first_, commands_, order_;
  std::vector<Slab> slabs_;
  size_t splatCount_ = 0, entryCount_ = 0;
  double nearestCenter_ = 0.0;
  bool countsKnown_ = false;
};

}  // namespace ewa
