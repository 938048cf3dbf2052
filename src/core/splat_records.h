// SplatRecord: one splat's footprint, optical depth and colour for a frame, made on the CPU by
// the same C++ the splat shaders mirror (shaders/splat_common.glsl, splatSetup), for the CPU
// splatter (core/tile_compositor.h).
#pragma once

#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/ewa_footprint.h"
#include "core/kernel_reach.h"
#include "core/shading.h"
#include "core/splat_attributes.h"
#include "core/splat_set.h"

namespace ewa {

// As the compute tiles' TileEwaSplat: (centre x, centre y, half width, half height) in pixels
// (y up, pixel centres at +0.5); (conic xx, xy, yy, optical depth at the centre); (camera
// depth, depth slope per pixel x and y, depth sigma); (colour rgb, normalized value). A splat
// not drawn has a zero record (no optical depth).
struct SplatRecord {
  glm::vec4 box{0.0f};
  glm::vec4 conic{0.0f};
  glm::vec4 depth{0.0f};
  glm::vec4 color{0.0f};
};

// The footprint of a kernel at camera-space `u` with camera covariance `cov`: computeFootprint,
// or (tests) a deliberately wrong one.
using FootprintFunction =
    std::function<Footprint(const glm::dvec3& u, const glm::dmat3& cov, const Projection& proj,
                            const FootprintParams& params)>;

// What every splat of a frame shares (the splat programs' uniforms, SplatRenderer's
// setCommonUniforms): the camera in the volume's own frame, the kernels, the projection, the
// transfer function's table and the clip region's camera-space half-spaces.
struct SplatFrameSetup {
  glm::dmat4 view{1.0};    // volume frame -> camera
  glm::dvec3 origin{0.0};  // voxel (i, j, k) sits at origin + (i, j, k) * spacing
  glm::dvec3 spacing{1.0};
  double kernelWidth = 1.0;  // kernelSigma
  Projection proj;
  FootprintParams params;
  KernelReach reach;
  double surfaceTau = 0.0;  // optical depth of a surface-splat layer along its normal
  Lighting lighting;
  // TransferFunction::bake over the volume's value range: (rgb, extinction per world unit),
  // read with linear interpolation as the GL's 1D texture reads it.
  std::vector<glm::vec4> transfer;
  std::vector<HalfSpace> clipPlanes;  // camera space; empty: nothing clipped
  // Post-classified composite: a splat carries its value and a unit extinction (its weight),
  // transparent voxels beside visible ones included (they shape the mean value).
  bool postClassified = false;
  FootprintFunction footprint = computeFootprint;
};

// The transfer table at normalized `value` as the splat shaders' texture() reads it.
glm::vec4 transferAt(const std::vector<glm::vec4>& table, float value);
glm::vec4 transferAt(const glm::vec4* table, int size, float value);

// Each splat's record for a frame (attributes: one per splat, or none). Pre-classified: the
// colour shaded with the voxel normal where the lighting is on and the splat has one, the
// optical depth the voxel's extinction times its volume (a surface splat's its layer's).
// Post-classified: the weight the voxel's volume, the colour its camera-space normal. The
// frame's shared terms are taken once; records are made on demand, from any thread.
class SplatRecordMaker {
 public:
  SplatRecordMaker(const SplatSet& splats, const AttributeList& attributes,
                   const SplatFrameSetup& setup);
  size_t size() const { return count_; }
  // Splat `index`'s record; a zero record where it is not drawn.
  SplatRecord operator()(size_t index) const;
  // Asks for splat `index`'s voxel and attributes from memory ahead of its record.
  void prefetch(size_t index) const {
    __builtin_prefetch(splats_ + index);
    if (attributes_) __builtin_prefetch(attributes_ + index);
  }

 private:
  const PackedSplat* splats_;
  const PackedAttributes* attributes_;  // null: none
  size_t count_;
  const SplatFrameSetup& setup_;
  glm::dmat3 rotation_;
  glm::dvec3 sigma_;
  glm::dmat3 covariance_;
  double voxelVolume_;
};

}  // namespace ewa
