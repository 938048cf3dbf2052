// SplatRecordMaker: splatSetup of shaders/splat_common.glsl on the CPU, splat by splat, from the
// footprint, reach, clip and shading C++ the shaders mirror.
#include "core/splat_records.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/clip_share.h"

namespace ewa {

glm::vec4 transferAt(const std::vector<glm::vec4>& table, float value) {
  return transferAt(table.data(), int(table.size()), value);
}

glm::vec4 transferAt(const glm::vec4* table, int n, float value) {
  // GL_LINEAR at (value * (n - 1) + 0.5) / n: between entries floor(x) and floor(x) + 1.
  if (n == 0) return glm::vec4(0.0f);
  const float x = std::clamp(value, 0.0f, 1.0f) * float(n - 1);
  const int i = std::min(int(x), n - 1);
  const int j = std::min(i + 1, n - 1);
  const float t = x - float(i);
  return table[i] * (1.0f - t) + table[j] * t;
}

namespace {

// One splat's record; false (the record left zero) where nothing is drawn.
bool setupSplat(const PackedSplat& s, const PackedAttributes* attributes, const SplatFrameSetup& f,
                const glm::dmat3& rotation, const glm::dmat3& volumeCov, const glm::dvec3& sigma,
                double voxelVolume, SplatRecord& out) {
  const float value = SplatSet::normalizedValue(s);
  // Post-classified splats carry their value, classified per pixel: no colour here.
  const glm::vec4 tf = f.postClassified ? glm::vec4(0.0f) : transferAt(f.transfer, value);
  UnpackedAttributes a;
  if (attributes) a = unpackAttributes(*attributes);
  // Post: zero-opacity voxels next to visible ones shape the mean value; they stay.
  if (!f.postClassified && !a.surface && !(tf.a > 0.0f)) return false;
  glm::dvec3 at = f.origin + glm::dvec3(SplatSet::i(s), SplatSet::j(s), SplatSet::k(s)) * f.spacing;
  glm::dmat3 cov = volumeCov;
  double mass = (f.postClassified ? 1.0 : double(tf.a)) * voxelVolume;
  if (a.surface) {
    at += a.normal * (a.offset * f.params.minSpacing);
    cov = surfaceCovariance(rotation, sigma, a.normal);
    mass = surfaceSplatMass(f.spacing, a.normal, f.surfaceTau);
  }
  const glm::dvec3 u(f.view * glm::dvec4(at, 1.0));
  // Cull before forming the Jacobian; kernels wholly outside the clip region (twice the reach:
  // the tail left on the kept side is negligible).
  const double radius = worldReach(f.reach, -u.z);
  if (cullKernel(u, radius, f.proj, f.params)) return false;
  if (!f.clipPlanes.empty() && clipCullsKernel(f.clipPlanes, u, 2.0 * radius)) return false;
  const Footprint fp = f.footprint(u, cov, f.proj, f.params);
  if (!fp.visible) return false;
  const glm::dvec3 toEye = f.proj.orthographic ? glm::dvec3(0.0, 0.0, 1.0) : glm::normalize(-u);
  const glm::dvec3 rgb =
      f.postClassified ? rotation * a.normal
                       : headlightShade(glm::dvec3(tf), rotation * a.normal, toEye, f.lighting);
  const double cutoff = f.params.cutoff;
  out.box = glm::vec4(glm::dvec4(fp.center, std::sqrt(cutoff * fp.covariance[0][0]),
                                 std::sqrt(cutoff * fp.covariance[1][1])));
  out.conic = glm::vec4(glm::dvec4(fp.conic[0][0], fp.conic[0][1], fp.conic[1][1], mass * fp.peak));
  out.depth = glm::vec4(glm::dvec4(fp.depth, fp.depthSlope, fp.depthSigma));
  out.color = glm::vec4(glm::vec3(rgb), value);
  return true;
}

}  // namespace

SplatRecordMaker::SplatRecordMaker(const SplatSet& splats, const AttributeList& attributes,
                                   const SplatFrameSetup& setup)
    : splats_(splats.splats().data()),
      attributes_(attributes.size() == splats.size() ? attributes.data() : nullptr),
      count_(splats.size()),
      setup_(setup),
      rotation_(setup.view),
      sigma_(kernelSigma(setup.spacing, setup.kernelWidth)),
      covariance_(cameraCovariance(rotation_, sigma_)),
      voxelVolume_(setup.spacing.x * setup.spacing.y * setup.spacing.z) {}

SplatRecord SplatRecordMaker::operator()(size_t index) const {
  SplatRecord record;
  setupSplat(splats_[index], attributes_ ? &attributes_[index] : nullptr, setup_, rotation_,
             covariance_, sigma_, voxelVolume_, record);
  return record;
}

}  // namespace ewa
