// Sheared grids resampled within each slice: the plan (QR of the voxel steps) and the sampling.
#include "core/shear_resample.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <type_traits>

#include "core/parallel_chunks.h"

namespace ewa {

namespace {

constexpr double kSlack = 1e-6;  // of a voxel: new voxels on an old slice's edge are inside it
constexpr double kPi = 3.14159265358979323846;

template <typename T>
T readAt(const uint8_t* base, size_t n) {
  T v;
  std::memcpy(&v, base + n * sizeof(T), sizeof(T));
  return v;
}

template <typename T>
void writeAt(uint8_t* base, size_t n, double value) {
  T v;
  if constexpr (std::is_floating_point_v<T>) {
    v = T(value);
  } else {
    const double lo = double(std::numeric_limits<T>::lowest());
    const double hi = double(std::numeric_limits<T>::max());
    v = T(std::clamp(std::round(value), lo, hi));
  }
  std::memcpy(base + n * sizeof(T), &v, sizeof(T));
}

// Planes [first, last) of the new grid, of voxel type T.
template <typename T>
void resamplePlanes(const ShearPlan& p, const OrientedGrid& g, double fill, size_t first,
                    size_t last, std::vector<uint8_t>& out) {
  const int64_t nx = g.dims[0], ny = g.dims[1];
  const int64_t mx = p.dims[0], my = p.dims[1];
  const glm::dmat3& t = p.shape;  // t[column][row]
  const uint8_t* in = g.bytes->data();
  const size_t plane = size_t(nx) * size_t(ny);
  auto inside = [](double u, int64_t n) { return u >= -kSlack && u <= double(n - 1) + kSlack; };
  for (size_t k = first; k < last; ++k) {
    const size_t oldBase = k * plane;
    const size_t newBase = k * size_t(mx) * size_t(my);
    for (int64_t jn = 0; jn < my; ++jn) {
      // Offsets in R's frame: y = t11 j + t21 k, x = t00 i + t10 j + t20 k.
      const double y = p.low.y + t[1][1] * double(jn);
      const double j = (y - t[2][1] * double(k)) / t[1][1];
      // Along a new row the old column moves by one voxel a voxel: one fraction a row.
      const double i0 = (p.low.x - t[1][0] * j - t[2][0] * double(k)) / t[0][0];
      const size_t row = newBase + size_t(jn) * size_t(mx);
      if (!inside(j, ny)) {
        for (int64_t col = 0; col < mx; ++col) writeAt<T>(out.data(), row + size_t(col), fill);
        continue;
      }
      const double jc = std::clamp(j, 0.0, double(ny - 1));
      const int64_t ja = std::min<int64_t>(int64_t(std::floor(jc)), std::max<int64_t>(ny - 2, 0));
      const int64_t jb = std::min<int64_t>(ja + 1, ny - 1);
      const double fj = jc - double(ja);
      for (int64_t col = 0; col < mx; ++col) {
        const double i = i0 + double(col);
        if (!inside(i, nx)) {
          writeAt<T>(out.data(), row + size_t(col), fill);
          continue;
        }
        const double ic = std::clamp(i, 0.0, double(nx - 1));
        const int64_t ia = std::min<int64_t>(int64_t(std::floor(ic)), std::max<int64_t>(nx - 2, 0));
        const int64_t ib = std::min<int64_t>(ia + 1, nx - 1);
        const double fi = ic - double(ia);
        auto at = [&](int64_t a, int64_t b) {
          return double(readAt<T>(in, oldBase + size_t(b) * size_t(nx) + size_t(a)));
        };
        // Weights of zero leave a neighbour out, so a NaN beside an exact sample stays out.
        double sum = 0.0;
        const double w[4] = {(1 - fi) * (1 - fj), fi * (1 - fj), (1 - fi) * fj, fi * fj};
        const double v[4] = {w[0] > 0 ? at(ia, ja) : 0.0, w[1] > 0 ? at(ib, ja) : 0.0,
                             w[2] > 0 ? at(ia, jb) : 0.0, w[3] > 0 ? at(ib, jb) : 0.0};
        for (int n = 0; n < 4; ++n)
          if (w[n] > 0) sum += w[n] * v[n];
        writeAt<T>(out.data(), row + size_t(col), sum);
      }
    }
  }
}

}  // namespace

ShearPlan planShearResample(const OrientedGrid& g, double maxGrowth) {
  ShearPlan p;
  if (isOrthonormal(g.direction)) {
    p.problem = "the direction is a rotation";
    return p;
  }
  const glm::dmat3 a(g.direction[0] * g.spacing.x, g.direction[1] * g.spacing.y,
                     g.direction[2] * g.spacing.z);
  const glm::dmat3 r = orthonormalized(g.direction);
  const glm::dmat3 t = glm::transpose(r) * a;
  // Gram-Schmidt made T upper triangular with a positive diagonal; a singular or non-finite D
  // (orthonormalized's identity) does not, and is left to the nearest rotation.
  bool triangular = true;
  for (int c = 0; c < 3; ++c) {
    const double length = glm::length(a[c]);
    if (!std::isfinite(length) || !(length > 0.0) || !(t[c][c] > 1e-9 * length)) triangular = false;
    for (int row = c + 1; row < 3; ++row)
      if (!(std::fabs(t[c][row]) <= 1e-9 * length)) triangular = false;
  }
  if (!triangular) {
    p.problem = "its axes are degenerate";
    return p;
  }
  for (int c = 0; c < 3; ++c) {
    const double cosine = std::clamp(t[c][c] / glm::length(a[c]), -1.0, 1.0);
    p.skewDegrees = std::max(p.skewDegrees, std::acos(cosine) * 180.0 / kPi);
  }
  // The old grid's extent in R's frame: T is linear, so its corners bound it.
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 ijk((corner & 1) ? double(g.dims[0] - 1) : 0.0,
                         (corner & 2) ? double(g.dims[1] - 1) : 0.0,
                         (corner & 4) ? double(g.dims[2] - 1) : 0.0);
    const glm::dvec3 at = t * ijk;
    lo = glm::min(lo, glm::dvec2(at));
    hi = glm::max(hi, glm::dvec2(at));
  }
  const double mx = std::ceil((hi.x - lo.x) / t[0][0] - kSlack) + 1.0;
  const double my = std::ceil((hi.y - lo.y) / t[1][1] - kSlack) + 1.0;
  const double growth = mx * my / (double(g.dims[0]) * double(g.dims[1]));
  if (!std::isfinite(growth) || growth > maxGrowth) {
    char times[32];
    std::snprintf(times, sizeof times, "%.3g", growth);  // any double: 1e+286 too
    p.problem = "the upright grid would hold " +
                (std::isfinite(growth) ? std::string(times) : std::string("too many")) +
                " times the voxels";
    return p;
  }
  p.ok = true;
  p.dims = {int64_t(mx), int64_t(my), g.dims[2]};
  p.spacing = {t[0][0], t[1][1], t[2][2]};
  p.direction = r;
  p.shape = t;
  p.low = {lo.x, lo.y, 0.0};
  p.origin = g.origin + r * p.low;
  return p;
}

std::vector<uint8_t> resampleShear(const ShearPlan& plan, const OrientedGrid& grid, ScalarType type,
                                   double fill, unsigned threads) {
  const size_t plane = size_t(plan.dims[0]) * size_t(plan.dims[1]);
  std::vector<uint8_t> out(plane * size_t(plan.dims[2]) * scalarSize(type));
  parallelChunks(size_t(plan.dims[2]), minItemsPerChunk(plane), threads,
                 [&](size_t first, size_t last, size_t) {
                   switch (type) {
                     case ScalarType::UInt8:
                       return resamplePlanes<uint8_t>(plan, grid, fill, first, last, out);
                     case ScalarType::Int16:
                       return resamplePlanes<int16_t>(plan, grid, fill, first, last, out);
                     case ScalarType::UInt16:
                       return resamplePlanes<uint16_t>(plan, grid, fill, first, last, out);
                     case ScalarType::Float32:
                       return resamplePlanes<float>(plan, grid, fill, first, last, out);
                   }
                 });
  return out;
}

double smallestValue(const std::vector<uint8_t>& bytes, ScalarType type) {
  const size_t n = bytes.size() / scalarSize(type);
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    double v = 0.0;
    switch (type) {
      case ScalarType::UInt8:
        v = bytes[i];
        break;
      case ScalarType::Int16:
        v = readAt<int16_t>(bytes.data(), i);
        break;
      case ScalarType::UInt16:
        v = readAt<uint16_t>(bytes.data(), i);
        break;
      case ScalarType::Float32:
        v = readAt<float>(bytes.data(), i);
        break;
    }
    if (std::isfinite(v)) best = std::min(best, v);
  }
  return std::isfinite(best) ? best : 0.0;
}

}  // namespace ewa
