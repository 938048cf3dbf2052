// CpuSplatter: the frame's setup from the render settings, the CPU splatting, the upload.
#include "render/cpu_splatter.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/clip_share.h"
#include "core/stopwatch.h"
#include "gl/gl_error.h"
#include "render/splat_renderer.h"

namespace ewa {

SplatFrameSetup cpuSplatSetup(const Volume& volume, const Camera& camera, const Projection& proj,
                              const RenderSettings& settings, const KernelReach& reach,
                              const std::vector<glm::vec4>& transfer) {
  SplatFrameSetup f;
  f.view = camera.viewMatrix();
  f.origin = volume.origin();
  f.spacing = volume.spacing();
  f.kernelWidth = settings.kernelWidth;
  f.proj = proj;
  f.params = footprintParams(settings, f.spacing);
  f.reach = reach;
  f.surfaceTau = -std::log(1.0 - std::clamp(settings.surfaceOpacity, 0.0, 0.999999));
  f.lighting = settings.lighting;
  f.transfer = transfer;
  f.postClassified = postClassified(settings);
  // As setClipUniforms: the region's half-spaces in this camera's space, as many as the
  // shaders take.
  for (const HalfSpace& h : halfSpacesInVolumeFrame(settings.clip, volume)) {
    if (f.clipPlanes.size() == size_t(ClipRegion::kMaxHalfSpaces)) break;
    f.clipPlanes.push_back(transformed(h, f.view));
  }
  return f;
}

TileNormals tileNormals(const RenderSettings& settings) {
  if (!postClassified(settings) || !settings.lighting.enabled) return TileNormals::None;
  if (SplatRenderer::fieldNormals(settings)) return TileNormals::Field;
  return SplatRenderer::rayNormals(settings) ? TileNormals::Ray : TileNormals::Voxel;
}

TileGather tileGather(const RenderSettings& settings) {
  if (settings.mode == RenderMode::XRay) return TileGather::XRay;
  if (settings.mode == RenderMode::Mip) return TileGather::Mip;
  return postClassified(settings) ? TileGather::Post : TileGather::Pre;
}

TileCompositeSettings cpuCompositeSettings(const SplatFrameSetup& setup,
                                           const RenderSettings& settings,
                                           const TileClassifyTables& tables,
                                           const glm::dmat4& cameraToIndex,
                                           const DataBox& dataBox) {
  TileCompositeSettings composite;
  composite.width = setup.proj.width;
  composite.height = setup.proj.height;
  composite.cutoff = settings.cutoff;
  composite.profile = depthProfile(settings);
  composite.termination = settings.terminationOpacity;
  composite.clipPlanes = setup.clipPlanes;
  composite.proj = setup.proj;
  composite.gather = tileGather(settings);
  composite.backToFront = settings.order == CompositeOrder::BackToFront;
  composite.samples = !settings.slabPreintegration ? 1 : settings.slabSamples >= 4 ? 4 : 2;
  composite.tables = tables;
  composite.cameraToIndex = cameraToIndex;
  composite.dataBox = dataBox;
  composite.normals = tileNormals(settings);
  composite.lighting = settings.lighting;
  return composite;
}

CpuSplatter::Timing CpuSplatter::compute(const ClassifiedSplats& splats,
                                         const std::vector<uint32_t>& order,
                                         const std::vector<Slab>& slabs,
                                         const SplatFrameSetup& setup,
                                         const TileCompositeSettings& composite,
                                         const std::atomic<bool>* cancel) {
  Timing t;
  const TileCompositor::Timing c =
      compositor_.draw(SplatRecordMaker(splats.splats, splats.attributes, setup), order, slabs,
                       composite, picture_, cancel);
  t.recordsMs = c.recordsMs;
  t.binMs = c.binMs;
  t.compositeMs = c.compositeMs;
  t.entries = c.entries;
  t.bytes = c.bytes;
  width_ = composite.width;
  height_ = composite.height;
  return t;
}

double CpuSplatter::upload() {
  const auto start = std::chrono::steady_clock::now();
  if (!texture_ || textureWidth_ != width_ || textureHeight_ != height_) {
    texture_ = gl::Texture::create2D(GL_RGBA32F, width_, height_);
    textureWidth_ = width_;
    textureHeight_ = height_;
  }
  texture_.subImage2D(0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, picture_.data());
  gl::checkGlError("CPU splatter picture upload");
  return millisecondsSince(start);
}

size_t CpuSplatter::bytes() const {
  return size_t(textureWidth_) * size_t(textureHeight_) * sizeof(glm::vec4);
}

}  // namespace ewa
