// Test volumes, transfer functions and image sums shared by the shear-warp unit tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <glm/geometric.hpp>
#include <vector>

#include "core/shear_warp.h"

namespace ewa::swtest {

using Field = std::function<double(int, int, int)>;

// An n^3 volume of `type` holding field(i, j, k) * scale + offset.
inline Volume makeVolume(int n, ScalarType type, const Field& field, double scale = 1.0,
                         double offset = 0.0) {
  const size_t count = size_t(n) * n * n;
  std::vector<uint8_t> bytes(count * scalarSize(type));
  size_t idx = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++idx) {
        const double v = field(i, j, k) * scale + offset;
        switch (type) {
          case ScalarType::UInt8:
            bytes[idx] = uint8_t(std::lround(v));
            break;
          case ScalarType::Int16: {
            const int16_t x = int16_t(std::lround(v));
            std::memcpy(&bytes[idx * 2], &x, 2);
            break;
          }
          case ScalarType::UInt16: {
            const uint16_t x = uint16_t(std::lround(v));
            std::memcpy(&bytes[idx * 2], &x, 2);
            break;
          }
          case ScalarType::Float32: {
            const float x = float(v);
            std::memcpy(&bytes[idx * 4], &x, 4);
            break;
          }
        }
      }
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), type, std::move(bytes));
}

// A smooth blob with values 0..200 and some structure for the transfer function to pick out.
inline double blob(int i, int j, int k) {
  const double x = i - 15.0, y = j - 14.0, z = k - 16.5;
  const double r = std::sqrt(x * x + y * y + z * z);
  return std::round(std::clamp(200.0 - 11.0 * r + 20.0 * std::sin(0.4 * i), 0.0, 200.0));
}

inline TransferFunction blobTf(double scale = 1.0, double offset = 0.0) {
  TransferFunction tf;
  auto s = [&](double v) { return v * scale + offset; };
  tf.opacity = {{s(20), 0.0}, {s(60), 0.05}, {s(120), 0.0}, {s(150), 0.4}, {s(200), 0.9}};
  tf.color = {{s(0), {1.0, 0.2, 0.1}}, {s(100), {0.2, 0.9, 0.3}}, {s(200), {0.9, 0.9, 1.0}}};
  tf.opacityUnitDistance = 1.0;
  return tf;
}

inline Camera obliqueCamera(const Volume& v, glm::dvec3 from) {
  Camera cam;
  cam.orthographic = true;
  cam.frame(v.boundsMin(), v.boundsMax(), from, glm::dvec3(0, 1, 0), 1.0);
  return cam;
}

inline FloatImage renderOnce(const Volume& v, const TransferFunction& tf, const Camera& cam,
                             const ShearWarpSettings& s, int size = 64) {
  ShearWarp sw;
  sw.setVolume(v);
  sw.setTransferFunction(tf);
  sw.render(cam, s, size, size);
  return sw.image();
}

inline double maxDifference(const FloatImage& a, const FloatImage& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.values.size(); ++i)
    worst = std::max(worst, double(std::abs(a.values[i] - b.values[i])));
  return worst;
}

inline double totalAlpha(const FloatImage& img) {
  double sum = 0.0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += img.at(x, y, 3);
  return sum;
}

// Standard and pre-integrated pictures of `cam` are the same with run-length encoding and two
// threads as without them on one (gtest assertions; include gtest first).
inline void expectRunsAndThreadsKeepThePicture(const Volume& v, const Camera& cam) {
  for (bool pre : {false, true})
    for (double scale : {1.0, 2.0}) {  // parallel: Lacroute's loop, and magnified
      ShearWarpSettings s;
      s.preintegrated = pre;
      s.intermediateScale = scale;
      s.threads = 2;
      const FloatImage fast = renderOnce(v, blobTf(), cam, s, 96);
      s.runLengthEncoding = false;
      s.threads = 1;
      const FloatImage plain = renderOnce(v, blobTf(), cam, s, 96);
      EXPECT_GT(totalAlpha(fast), 100.0);
      EXPECT_EQ(fast.values, plain.values) << "preintegrated " << pre << " scale " << scale;
    }
}

}  // namespace ewa::swtest
