// Filter-quality measurement: renders, the supersampled reference, the metrics per mode.
#include "bench/quality_benchmark.h"

#include <cmath>
#include <stdexcept>

#include "bench/sheet_ray_image.h"
#include "core/image_resample.h"
#include "io/image_convert.h"

namespace ewa {

namespace {

constexpr double kPi = 3.14159265358979323846;

int referenceMargin(const QualityOptions& o) {
  return int(std::ceil(4.0 * o.sigma));
}

FloatImage renderFloat(SplatRenderer& renderer, const Camera& camera, FilterMode filter, int size,
                       const QualityOptions& o) {
  RenderSettings settings;
  settings.classification.mode = o.classification;
  settings.lowPass = o.lowPass;
  settings.filter = filter;
  settings.kernelWidth = o.kernelWidth;
  settings.cutoff = o.cutoff;
  renderer.render(camera, settings, size, size);
  return toFloatImage(renderer.readImage());
}

// Mean frame-to-frame change over `mask` along the sequence of sub-pixel moves.
// `first` is the image at the unmoved camera.
template <typename RenderFn>
double flickerOf(RenderFn render, const FloatImage& first, const Camera& camera,
                 const QualityOptions& o, const PixelMask& mask) {
  FloatImage previous = first;
  double sum = 0.0;
  for (int f = 1; f <= o.frames; ++f) {
    // A diagonal path (golden-ratio slope) so neither image axis is favoured.
    const double t = f * o.stepPixels;
    FloatImage current = render(shiftedCamera(camera, o.size, o.size, t, 0.618 * t));
    sum += meanAbsoluteDifference(previous, current, mask);
    previous = std::move(current);
  }
  return sum / o.frames;
}

void fillErrors(ModeResult* m, const FloatImage& reference, const SheetRegions& regions) {
  m->rmseAll = rootMeanSquareError(m->image, reference);
  m->psnrAll = peakSignalToNoiseRatio(m->rmseAll, 1.0);
  m->rmseBeyond = rootMeanSquareError(m->image, reference, &regions.beyondK);
  m->psnrBeyond = peakSignalToNoiseRatio(m->rmseBeyond, 1.0);
}

}  // namespace

int referenceRenderSize(const QualityOptions& o) {
  return (o.size + 2 * referenceMargin(o)) * o.supersample;
}

namespace {
// A wider view angle with the same focal length in pixels, for the reference's margin: the
// principal point stays at the centre, so the central size x size pixels are exactly the
// original frame.
Camera widened(const Camera& camera, const QualityOptions& o) {
  const int big = o.size + 2 * referenceMargin(o);
  Camera wide = camera;
  const double halfTan = std::tan(camera.viewAngleDeg * kPi / 360.0) * big / o.size;
  wide.viewAngleDeg = std::atan(halfTan) * 360.0 / kPi;
  return wide;
}

FloatImage lowPassAndCrop(const FloatImage& fine, const QualityOptions& o) {
  return cropImage(gaussianDecimate(fine, o.supersample, o.sigma), referenceMargin(o), o.size,
                   o.size);
}
}  // namespace

FloatImage rayReference(const Volume& sheet, const TransferFunction& tf, const Camera& camera,
                        const QualityOptions& o) {
  const int fine = referenceRenderSize(o);
  return lowPassAndCrop(sheetRayImage(sheet, tf, widened(camera, o), fine, fine,
                                      RenderSettings().background, o.kernelWidth),
                        o);
}

FloatImage renderReference(SplatRenderer& renderer, const Camera& camera, FilterMode filter,
                           const QualityOptions& o) {
  return lowPassAndCrop(
      renderFloat(renderer, widened(camera, o), filter, referenceRenderSize(o), o), o);
}

SceneQuality measureScene(SplatRenderer& renderer, const QualityScene& scene,
                          const SyntheticVolume& volume, const QualityOptions& o) {
  if (o.size < 8 || o.supersample < 1 || o.frames < 0 || !(o.sigma > 0.0) || !(o.stepPixels > 0.0))
    throw std::invalid_argument("quality benchmark: options out of range");
  renderer.setVolume(volume.volume);
  TransferFunction tf = *volume.transferFunction;
  if (o.sheetOpacity > 0.0 && o.sheetOpacity < 1.0)
    for (auto& point : tf.opacity)
      if (point.alpha > 0.0) point.alpha = o.sheetOpacity;
  renderer.setTransferFunction(tf);
  SceneQuality q;
  q.scene = scene;
  const Camera camera = scene.camera();
  q.regions = sheetRegions(volume.volume, camera, o.size, o.size);

  // The reference is the paper's ideal resampled image: the continuous image of the
  // reconstructed volume convolved with the unit Gaussian low-pass. It is integrated along
  // rays on the CPU, so an error the filters share (in the Jacobian, the conic, the slabs)
  // shows against it instead of being built into it.
  auto reference = [&](const Camera& c) { return rayReference(volume.volume, tf, c, o); };
  q.reference.name = "reference";
  q.reference.image = reference(camera);
  if (o.splatReference) {
    const FloatImage old = renderReference(renderer, camera, FilterMode::Ewa, o);
    q.splatReferenceRmseAll = rootMeanSquareError(old, q.reference.image);
    q.splatReferenceRmseBeyond = rootMeanSquareError(old, q.reference.image, &q.regions.beyondK);
  }
  q.reference.contrast = 1.0;
  q.reference.gain = 1.0;
  if (o.referenceFlicker && o.frames > 0)
    q.reference.flicker = flickerOf(reference, q.reference.image, camera, o, q.regions.beyondK);
  const double refContrast = rmsContrast(q.reference.image, q.regions.anisotropic);

  for (FilterMode filter : {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain}) {
    ModeResult m;
    m.name = filterModeName(filter);
    auto render = [&](const Camera& c) { return renderFloat(renderer, c, filter, o.size, o); };
    m.image = render(camera);
    fillErrors(&m, q.reference.image, q.regions);
    if (o.frames > 0) m.flicker = flickerOf(render, m.image, camera, o, q.regions.beyondK);
    if (maskCount(q.regions.anisotropic) > 0 && refContrast > 0.0) {
      m.contrast = rmsContrast(m.image, q.regions.anisotropic) / refContrast;
      m.gain = signalGain(m.image, q.reference.image, q.regions.anisotropic);
    }
    q.modes.push_back(std::move(m));
  }
  return q;
}

}  // namespace ewa
