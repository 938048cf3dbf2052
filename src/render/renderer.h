// Renderer: the interface every volume renderer implements, and the settings they share.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/ewa_footprint.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/png_io.h"

namespace ewa {

enum class RenderMode { Composite = 0, XRay = 1 };

const char* renderModeName(RenderMode mode);
bool parseRenderMode(const std::string& text, RenderMode* mode);

struct RenderSettings {
  FilterMode filter = FilterMode::Ewa;
  RenderMode mode = RenderMode::Composite;
  double cutoff = 4.0;         // footprint cutoff r = dx^T Q dx
  double slabThickness = 1.0;  // in units of the smallest voxel spacing
  glm::dvec3 background{0.0};
};

// The footprint parameters every splat of a volume with this spacing gets under `settings`:
// Swan's s is the smallest spacing, and voxels closer than it to the eye plane are culled.
FootprintParams footprintParams(const RenderSettings& settings, const glm::dvec3& spacing);

struct RenderStats {
  size_t splatsTotal = 0;   // non-transparent voxels
  size_t splatsDrawn = 0;   // in front of the eye, sent to the GPU this frame
  size_t slabs = 0;
  bool quadPass = false;    // some footprints exceeded the point-size limit
  double cpuMs = 0.0;       // CPU time of the last render() call, GPU work included (it waits)
  // Time per stage of the last render() call, for the statistics panel; 0 where a renderer
  // does not measure it (classify: splats from the transfer function; sort: slab bucketing;
  // splat: drawing the kernels; composite: blending slabs and the final pass).
  double classifyMs = 0.0;
  double sortMs = 0.0;
  double splatMs = 0.0;
  double compositeMs = 0.0;
  size_t gpuBytes = 0;      // bytes of GL buffers and textures the renderer holds; 0: not counted
};

class Renderer {
 public:
  virtual ~Renderer() = default;
  // The volume must outlive the renderer or the next setVolume call.
  virtual void setVolume(const Volume& volume) = 0;
  virtual void setTransferFunction(const TransferFunction& tf) = 0;
  // Renders into the renderer's own output image of width x height pixels.
  virtual void render(const Camera& camera, const RenderSettings& settings, int width,
                      int height) = 0;
  // The last image, top row first, RGB over the background.
  virtual Image8 readImage() const = 0;
  // GL texture name of the last image (RGBA8, bottom row first), for drawing it in a window.
  virtual unsigned outputTexture() const = 0;
  virtual RenderStats stats() const = 0;
};

}  // namespace ewa
