// CPU ray integration through a sheet of 3D Gaussian kernels: the independent quality reference.
#include "bench/sheet_ray_image.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>
#include <thread>
#include <vector>

namespace ewa {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kReach = 4.5;  // kernels are kept within this many standard deviations (e^-10)

struct KernelOnRay {
  double t;        // mean along the ray
  double weight;   // optical depth the kernel adds along the whole ray
  glm::dvec3 rgb;  // its colour
};

struct SheetKernels {
  const Volume& sheet;
  glm::dvec3 sigma;         // the kernels' standard deviations per axis (kernel width x spacing)
  std::vector<double> tau;  // extinction per voxel
  std::vector<glm::dvec3> color;
};

// The kernels the ray o + t d (d unit) passes within kReach standard deviations of, with their
// line integrals. Walks the voxel columns i the ray's x range covers and, per column, the rows
// j its y range covers there.
void kernelsOnRay(const SheetKernels& k, const glm::dvec3& o, const glm::dvec3& d,
                  std::vector<KernelOnRay>& out) {
  out.clear();
  const Volume& v = k.sheet;
  const glm::dvec3 s = k.sigma, inv2 = 1.0 / (s * s);
  const glm::dvec3 lo = v.boundsMin() - kReach * s, hi = v.boundsMax() + kReach * s;
  // Clip the ray to the volume's box widened by the reach.
  double t0 = 0.0, t1 = 1e300;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-300) {
      if (o[a] < lo[a] || o[a] > hi[a]) return;
      continue;
    }
    double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1)) return;
  const double a = glm::dot(d * d, inv2);
  const double lineNorm = std::sqrt(2.0 * kPi / a) / (std::pow(2.0 * kPi, 1.5) * s.x * s.y * s.z);
  const glm::dvec3 spacing = v.spacing();
  const double mass = spacing.x * spacing.y * spacing.z;  // a voxel's, whatever its kernel's width
  const int64_t nx = v.dims()[0], ny = v.dims()[1];
  const glm::dvec3 org = v.origin();
  auto column = [&](double x) { return (x - org.x) / spacing.x; };
  auto row = [&](double y) { return (y - org.y) / spacing.y; };
  const double xa = o.x + t0 * d.x, xb = o.x + t1 * d.x;
  const int64_t i0 =
      std::max<int64_t>(0, int64_t(std::floor(column(std::min(xa, xb) - kReach * s.x))));
  const int64_t i1 =
      std::min<int64_t>(nx - 1, int64_t(std::ceil(column(std::max(xa, xb) + kReach * s.x))));
  for (int64_t i = i0; i <= i1; ++i) {
    // The part of the clipped ray within reach of column i in x.
    double u0 = t0, u1 = t1;
    const double x = org.x + double(i) * spacing.x;
    if (std::abs(d.x) > 1e-300) {
      double ta = (x - kReach * s.x - o.x) / d.x, tb = (x + kReach * s.x - o.x) / d.x;
      if (ta > tb) std::swap(ta, tb);
      u0 = std::max(u0, ta);
      u1 = std::min(u1, tb);
      if (!(u0 <= u1)) continue;
    }
    const double ya = o.y + u0 * d.y, yb = o.y + u1 * d.y;
    const int64_t j0 =
        std::max<int64_t>(0, int64_t(std::floor(row(std::min(ya, yb) - kReach * s.y))));
    const int64_t j1 =
        std::min<int64_t>(ny - 1, int64_t(std::ceil(row(std::max(ya, yb) + kReach * s.y))));
    for (int64_t j = j0; j <= j1; ++j) {
      const size_t index = size_t(j * nx + i);
      const double tau = k.tau[index];
      if (!(tau > 0.0)) continue;
      const glm::dvec3 q = o - v.worldPosition(double(i), double(j), 0.0);
      const double b = glm::dot(d * q, inv2), c = glm::dot(q * q, inv2);
      const double m = c - b * b / a;  // squared Mahalanobis distance of the ray to the centre
      if (m > kReach * kReach) continue;
      out.push_back({-b / a, tau * mass * lineNorm * std::exp(-0.5 * m), k.color[index]});
    }
  }
}

// Front-to-back emission-absorption along one ray through its kernels (all of along-ray
// standard deviation sigma), over `background`.
glm::dvec3 integrateRay(const std::vector<KernelOnRay>& kernels, double sigma,
                        const glm::dvec3& background, std::vector<double>& depth,
                        std::vector<glm::dvec3>& emission, std::vector<double>& taps) {
  if (kernels.empty()) return background;
  double tMin = 1e300, tMax = -1e300;
  for (const KernelOnRay& k : kernels) {
    tMin = std::min(tMin, k.t);
    tMax = std::max(tMax, k.t);
  }
  const double h = 0.25 * sigma;
  const int reach = int(std::ceil(5.0 * sigma / h));
  const double start = tMin - (reach + 1) * h;
  const size_t bins = size_t(std::ceil((tMax - start) / h)) + size_t(reach) + 3;
  // Each kernel's weight and colour-weight at its mean, split linearly between two bins.
  std::vector<double> w(bins, 0.0);
  std::vector<glm::dvec3> wc(bins, glm::dvec3(0.0));
  for (const KernelOnRay& k : kernels) {
    const double x = (k.t - start) / h;
    const size_t b = size_t(x);
    const double f = x - double(b);
    w[b] += (1.0 - f) * k.weight;
    w[b + 1] += f * k.weight;
    wc[b] += (1.0 - f) * k.weight * k.rgb;
    wc[b + 1] += f * k.weight * k.rgb;
  }
  // Convolved with the along-ray Gaussian (taps sum to 1): optical depth per bin.
  taps.resize(size_t(2 * reach + 1));
  double norm = 0.0;
  for (int r = -reach; r <= reach; ++r)
    norm += taps[size_t(r + reach)] = std::exp(-0.5 * (r * h / sigma) * (r * h / sigma));
  for (double& t : taps) t /= norm;
  depth.assign(bins, 0.0);
  emission.assign(bins, glm::dvec3(0.0));
  for (size_t b = 0; b < bins; ++b) {
    if (w[b] == 0.0) continue;
    for (int r = -reach; r <= reach; ++r) {
      const int64_t at = int64_t(b) + r;
      if (at < 0 || at >= int64_t(bins)) continue;
      depth[size_t(at)] += taps[size_t(r + reach)] * w[b];
      emission[size_t(at)] += taps[size_t(r + reach)] * wc[b];
    }
  }
  glm::dvec3 color(0.0);
  double transmittance = 1.0;
  for (size_t b = 0; b < bins; ++b) {
    if (depth[b] <= 0.0) continue;
    const double alpha = 1.0 - std::exp(-depth[b]);
    color += transmittance * alpha * (emission[b] / depth[b]);
    transmittance *= 1.0 - alpha;
  }
  return color + transmittance * background;
}

}  // namespace

FloatImage sheetRayImage(const Volume& sheet, const TransferFunction& tf, const Camera& camera,
                         int width, int height, const glm::dvec3& background, double kernelWidth,
                         int threads) {
  if (sheet.dims()[2] != 1)
    throw std::invalid_argument("sheetRayImage: the volume must be one voxel thick along z");
  if (camera.orthographic)
    throw std::invalid_argument("sheetRayImage: the camera must be perspective");
  if (!(kernelWidth > 0.0) || !std::isfinite(kernelWidth))
    throw std::invalid_argument("sheetRayImage: the kernel width must be positive");
  SheetKernels kernels{sheet, kernelWidth * sheet.spacing(), {}, {}};
  const size_t n = size_t(sheet.dims()[0] * sheet.dims()[1]);
  kernels.tau.resize(n);
  kernels.color.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double value = sheet.valueAt(int64_t(i));
    kernels.tau[i] = std::isfinite(value) ? tf.extinctionAt(value) : 0.0;
    kernels.color[i] = tf.colorAt(value);
  }
  const Projection proj = camera.projection(width, height);
  const glm::dmat3 toWorld = glm::transpose(camera.rotation());
  const glm::dvec3 inv2 = 1.0 / (kernels.sigma * kernels.sigma);
  FloatImage image(width, height, 3);
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  auto work = [&](int first) {
    std::vector<KernelOnRay> onRay;
    std::vector<double> depth, taps;
    std::vector<glm::dvec3> emission;
    for (int row = first; row < height; row += threads) {
      const double py = double(height - 1 - row) + 0.5;  // pixel coordinates have y up
      for (int x = 0; x < width; ++x) {
        const glm::dvec3 dirCam((x + 0.5 - proj.principal.x) / proj.focalPixels,
                                (py - proj.principal.y) / proj.focalPixels, -1.0);
        const glm::dvec3 d = glm::normalize(toWorld * dirCam);
        kernelsOnRay(kernels, camera.position, d, onRay);
        const double sigma = 1.0 / std::sqrt(glm::dot(d * d, inv2));
        const glm::dvec3 c = integrateRay(onRay, sigma, background, depth, emission, taps);
        for (int ch = 0; ch < 3; ++ch) image.at(x, row, ch) = float(c[ch]);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
  return image;
}

}  // namespace ewa
