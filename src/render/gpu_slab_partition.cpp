// GpuSlabPartition: the four compute passes of shaders/slab_partition.comp.glsl and the little
// the CPU reads back (the depth range; the per-slab counts only when asked).
#include "render/gpu_slab_partition.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

#include "core/ewa_footprint.h"
#include "gl/gl_error.h"

namespace ewa {

namespace {

constexpr size_t kGroup = 256;  // local size of the per-splat passes
constexpr uint32_t kAll = 0xffffffffu;

// The inverse of orderedBits in the shader.
float fromOrderedBits(uint32_t u) {
  const uint32_t bits = (u & 0x80000000u) ? (u & 0x7fffffffu) : ~u;
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace

GpuSlabPartition::GpuSlabPartition(const gl::ShaderLibrary& shaders)
    : extentPass_(shaders.computeProgram("slab_partition.comp.glsl", "#define EXTENT_PASS 1\n")),
      countPass_(shaders.computeProgram("slab_partition.comp.glsl", "#define COUNT_PASS 1\n")),
      scanPass_(shaders.computeProgram("slab_partition.comp.glsl", "#define SCAN_PASS 1\n")),
      scatterPass_(shaders.computeProgram("slab_partition.comp.glsl", "#define SCATTER_PASS 1\n")),
      range_(gl::Buffer::create(5 * sizeof(uint32_t))) {}

void GpuSlabPartition::build(const gl::Buffer& splats, const gl::Buffer& attributes, size_t n,
                             bool surfaces, const glm::dvec3& origin, const glm::dmat4& view,
                             double thickness, double nearCull, const DepthExtent& extent) {
  slabs_.clear();
  splatCount_ = entryCount_ = 0;
  nearestCenter_ = INFINITY;
  countsKnown_ = true;
  if (n == 0 || !(thickness > 0.0)) return;
  countsKnown_ = false;
  const glm::dvec3& spacing = extent.spacing;
  // As in SlabPartition::build: depth is affine in (i,j,k).
  const glm::dvec3 row(-view[0][2], -view[1][2], -view[2][2]);
  const double d0 = glm::dot(row, origin) - view[3][2];
  const KernelReach& k = extent.reach;
  const glm::dvec3 sigma = kernelSigma(spacing, extent.kernelWidth);
  const double volumeVariance = cameraCovariance(extent.rotation, sigma)[2][2];
  const double minSpacing = std::min({spacing.x, spacing.y, spacing.z});
  // Every per-splat pass forms each splat's extent from these (splatExtent in the shader).
  for (gl::Program* e : {&extentPass_, &countPass_, &scatterPass_}) {
    e->setUInt("uCount", GLuint(n));
    e->setDouble("uD0", d0);
    e->setDVec3("uDijk", row * spacing);
    e->setDVec3("uRow", row);
    e->setDouble("uVolumeVariance", volumeVariance);
    e->setDMat3("uRotation", extent.rotation);
    e->setDVec3("uSigma", sigma);
    e->setDouble("uCullDepth", nearCull);
    e->setInt("uSurfaces", surfaces ? 1 : 0);
    e->setDouble("uCutoff", k.cutoff);
    e->setDouble("uDepthCutoff", k.depthCutoff);
    e->setDouble("uMaxSigma", k.maxSigma);
    e->setDouble("uMinSpacing", minSpacing);
    e->setDouble("uSwanSpacing", k.swanSpacing);
    e->setInt("uSwan", k.swan ? 1 : 0);
    e->setInt("uOrthographic", k.orthographic ? 1 : 0);
    e->setDouble("uFocalPixels", k.focalPixels);
    e->setDouble("uPixelsPerUnit", k.pixelsPerUnit);
  }
  const uint32_t init[5] = {kAll, 0u, kAll, 0u, 0u};
  range_.setSubData(0, sizeof init, init);
  splats.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  attributes.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  range_.bindBase(GL_SHADER_STORAGE_BUFFER, 5);
  gl::dispatchOver(extentPass_, n, kGroup);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  // The first of the partition's two waits: the slab count sizes the passes and the CPU's slab
  // loop.
  uint32_t range[5];
  range_.getSubData(0, sizeof range, range);
  splatCount_ = range[3];
  if (splatCount_ == 0) {
    glUseProgram(0);
    countsKnown_ = true;
    return;
  }
  const double lo = slabGridStart(fromOrderedBits(range[0]), thickness, extent.anchorDepth);
  const double hi = fromOrderedBits(range[1]);
  nearestCenter_ = fromOrderedBits(range[2]);
  // Slab planes exactly as SlabPartition::build places them.
  const double count = std::min(std::floor((hi - lo) / thickness) + 1.0, 1.0e6);
  const auto slabCount = static_cast<size_t>(count);
  const double scale = count < 1.0e6 ? 1.0 / thickness : count / (hi - lo) * (1.0 - 1e-9);
  cursor_.reserve(GLsizeiptr(slabCount * sizeof(uint32_t)), "slab partition buffers");
  first_.reserve(GLsizeiptr(slabCount * sizeof(uint32_t)), "slab partition buffers");
  commands_.reserve(GLsizeiptr(slabCount * 8 * sizeof(uint32_t)), "slab partition buffers");
  const uint32_t zero = 0;
  glClearNamedBufferSubData(cursor_.id(), GL_R32UI, 0, GLsizeiptr(slabCount * sizeof(uint32_t)),
                            GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  for (gl::Program* p : {&countPass_, &scanPass_, &scatterPass_}) {
    p->setUInt("uSlabCount", GLuint(slabCount));
    p->setDouble("uLo", lo);
    p->setDouble("uScale", scale);
  }
  first_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  cursor_.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  commands_.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  gl::dispatchOver(countPass_, n, kGroup);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  gl::dispatchOver(scanPass_, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  // The second wait: the order list is made exactly as long as its entries (a bound from the
  // extents alone, a splat's length in slabs rounded up plus one, held a third more; a 512^3
  // volume's list is hundreds of megabytes).
  uint32_t entries = 0;
  range_.getSubData(4 * sizeof(uint32_t), sizeof entries, &entries);
  order_.reserve(GLsizeiptr(size_t(entries) * sizeof(uint32_t)), "slab partition buffers");
  entryCount_ = entries;
  order_.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  gl::dispatchOver(scatterPass_, n, kGroup);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(0);
  slabs_.resize(slabCount);
  for (size_t b = 0; b < slabCount; ++b) slabs_[b] = {lo + b / scale, lo + (b + 1) / scale, 0, 0};
  gl::checkGlError("GpuSlabPartition::build");
}

void GpuSlabPartition::readCounts() {
  if (countsKnown_) return;
  const size_t n = slabs_.size();
  std::vector<uint32_t> first(n), end(n);
  first_.getSubData(0, GLsizeiptr(n * sizeof(uint32_t)), first.data());
  cursor_.getSubData(0, GLsizeiptr(n * sizeof(uint32_t)), end.data());  // first + count now
  for (size_t b = 0; b < n; ++b) {
    slabs_[b].first = first[b];
    slabs_[b].count = end[b] - first[b];
  }
  countsKnown_ = true;
}

std::vector<uint32_t> GpuSlabPartition::readOrder() const {
  if (slabs_.empty() || !countsKnown_) return {};
  const size_t total = slabs_.back().first + slabs_.back().count;
  std::vector<uint32_t> order(total);
  if (total) order_.getSubData(0, GLsizeiptr(total * sizeof(uint32_t)), order.data());
  return order;
}

void GpuSlabPartition::bindForDrawing() const {
  order_.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  first_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
}

size_t GpuSlabPartition::bytes() const {
  return size_t(range_.size() + cursor_.size() + first_.size() + commands_.size() + order_.size());
}

}  // namespace ewa
