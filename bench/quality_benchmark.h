// The filter-quality measurement: each filter mode against a supersampled reference, with
// error, flicker beyond k and contrast kept where kernels are anisotropic.
#pragma once

#include <string>
#include <vector>

#include "bench/quality_scene.h"
#include "core/ewa_footprint.h"
#include "core/image_metrics.h"
#include "core/synthetic_volume.h"
#include "render/splat_renderer.h"

namespace ewa {

struct QualityOptions {
  int size = 256;                // output image width and height
  int supersample = 8;           // reference rays per output pixel along each axis
  int frames = 8;                // sub-pixel camera moves for the flicker measure
  double stepPixels = 0.25;      // image motion per move, in output pixels
  double sigma = 1.0;            // the reference's Gaussian low-pass, in output pixels
  bool referenceFlicker = true;  // also render the reference at every move (costly)
  bool splatReference = true;    // also make the old reference (EWA splats at supersample x)
  double sheetOpacity = -1.0;    // in (0, 1): replaces the sheet's opacity per voxel; else kept
  double kernelWidth = RenderSettings().kernelWidth;  // of the splats (and the splat reference)
  double cutoff = RenderSettings().cutoff;            // of their footprints
  // The filters are compared pre-classified, as the papers do and as the reference is made;
  // post-classified to hold the default mode to the same anti-aliasing.
  ClassificationMode classification = ClassificationMode::Pre;
  double lowPass = 0.0;  // RenderSettings::lowPass (0: automatic)
};

// Metrics of one image against the reference. Errors are over RGB in [0, 1].
struct ModeResult {
  std::string name;                       // "ewa", "swan", "plain" or "reference"
  FloatImage image;                       // first frame
  double rmseAll = 0, psnrAll = 0;        // over the whole image
  double rmseBeyond = 0, psnrBeyond = 0;  // over the sheet beyond k
  double flicker = -1;  // mean |frame-to-frame change| over the sheet beyond k (-1: not run)
  double contrast = 0;  // RMS contrast over the anisotropic region / the reference's
  double gain = 0;      // signalGain against the reference over the anisotropic region
};

struct SceneQuality {
  QualityScene scene;
  SheetRegions regions;
  ModeResult reference;  // rays through the sheet on the CPU, low-passed and decimated
  // The old reference, EWA splats at supersample x low-passed the same way: how far it is from
  // the ray-integrated one (splatReference only).
  double splatReferenceRmseAll = 0;
  double splatReferenceRmseBeyond = 0;
  std::vector<ModeResult> modes;  // ewa, swan, plain
};

// The size of the supersampled image the reference needs (margin included).
int referenceRenderSize(const QualityOptions& options);

// The reference: the continuous image of the sheet, by integration along rays on the CPU
// (sheetRayImage, no EWA footprint code) at supersample x the resolution (plus a margin of
// 4 sigma, so the low-pass sees what lies just outside the frame), low-passed with a Gaussian
// of sigma output pixels and decimated to size x size.
FloatImage rayReference(const Volume& sheet, const TransferFunction& tf, const Camera& camera,
                        const QualityOptions& options);

// The same from `renderer`'s picture with `filter` at supersample x (the reference before the
// ray-integrated one, which shared the footprint code with the filters it judged).
FloatImage renderReference(SplatRenderer& renderer, const Camera& camera, FilterMode filter,
                           const QualityOptions& options);

// Measures one scene; the volume must be a sheet (see sheetRegions). Throws
// std::invalid_argument for options out of range.
SceneQuality measureScene(SplatRenderer& renderer, const QualityScene& scene,
                          const SyntheticVolume& volume, const QualityOptions& options);

}  // namespace ewa
