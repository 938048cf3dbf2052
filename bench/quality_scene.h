// The filter-quality benchmark's scenes (Swan's checkerboard, Zwicker's zebra sheets) and the
// image regions its measures use: beyond the distance k, and where kernels are anisotropic.
#pragma once

#include <string>
#include <vector>

#include "bench/image_statistics.h"
#include "core/camera.h"
#include "core/volume.h"

namespace ewa {

struct QualityScene {
  std::string spec;     // --synthetic spec of a one-voxel-thick sheet in the plane z = 0
  std::string caption;  // what it reproduces
  glm::dvec3 position{0.0};
  glm::dvec3 focalPoint{0.0};
  glm::dvec3 viewUp{0.0, 0.0, 1.0};
  double viewAngleDeg = 30.0;

  Camera camera() const;
};

// checkerboard:10 receding to the horizon (Swan et al., Fig. 7), and zebra:2 and zebra:4
// receding along their coarse axis (Zwicker et al., Fig. 8: 2:1 and 4:1 kernels).
std::vector<QualityScene> qualityScenes();

// Regions of a width x height image of a sheet volume (dims nx x ny x 1) seen by `camera`.
// A pixel belongs to the sheet when the ray through its centre meets the plane of the voxel
// centres inside the lattice; its depth is that point's distance in front of the eye plane.
struct SheetRegions {
  int width = 0;
  int height = 0;
  double k = 0.0;             // Swan's k = s * focal length in pixels (s: smallest spacing)
  std::vector<float> depth;   // per pixel; 0 off the sheet
  std::vector<float> aspect;  // major / minor axis of the reconstruction footprint there
  PixelMask sheet;            // the ray meets the sheet
  PixelMask beyondK;          // ... at depth > k: more than one voxel per pixel (see below)
  PixelMask anisotropic;      // ... beyond k, with footprint aspect >= kAnisotropicAspect
};

constexpr double kAnisotropicAspect = 1.5;
// beyondK and anisotropic leave out sheet pixels this close (in pixels, either axis) to the
// sheet's silhouette: there the modes differ by how far their kernels spread past the edge
// (Swan's stretched kernels fatten the horizon), not by how they filter the texture.
constexpr int kSilhouetteMargin = 2;

// Throws std::invalid_argument when the volume is not one voxel thick.
SheetRegions sheetRegions(const Volume& sheet, const Camera& camera, int width, int height);

// The camera turned about its eye so that the image moves by (dx, dy) pixels at its centre:
// the benchmark's sub-pixel camera moves.
Camera shiftedCamera(const Camera& camera, int width, int height, double dx, double dy);

}  // namespace ewa
