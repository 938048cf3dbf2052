// TfCanvas: maps transfer-function values and opacities to editor pixels and picks points (no
// ImGui).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/transfer_function.h"

namespace ewa {

// The editor's plot: value runs left to right over [lo, hi], opacity bottom (0) to top (1), in
// screen pixels with y down. Kept free of ImGui so the mouse logic can be unit tested.
struct TfCanvas {
  float x = 0, y = 0, width = 1, height = 1;  // top-left corner and size in pixels
  double lo = 0, hi = 1;                      // value range shown

  double span() const { return hi > lo ? hi - lo : 1.0; }
  float toX(double value) const { return x + float((value - lo) / span()) * width; }
  float toY(double alpha) const { return y + float(1.0 - alpha) * height; }
  // Screen to data, clamped to the plot.
  double toValue(float px) const {
    return lo + std::clamp(double(px - x) / width, 0.0, 1.0) * span();
  }
  double toAlpha(float py) const { return std::clamp(1.0 - double(py - y) / height, 0.0, 1.0); }

  // Index of the opacity point nearest (px, py) within `radius` pixels, or -1.
  int pickOpacity(const TransferFunction& tf, float px, float py, float radius) const {
    int best = -1;
    float bestDistance = radius * radius;
    for (size_t i = 0; i < tf.opacity.size(); ++i) {
      const float dx = toX(tf.opacity[i].value) - px, dy = toY(tf.opacity[i].alpha) - py;
      if (dx * dx + dy * dy <= bestDistance) {
        bestDistance = dx * dx + dy * dy;
        best = int(i);
      }
    }
    return best;
  }
  // Index of the colour point whose marker is nearest px (horizontally) within `radius`, or -1.
  int pickColor(const TransferFunction& tf, float px, float radius) const {
    int best = -1;
    float bestDistance = radius;
    for (size_t i = 0; i < tf.color.size(); ++i) {
      const float d = std::fabs(toX(tf.color[i].value) - px);
      if (d <= bestDistance) {
        bestDistance = d;
        best = int(i);
      }
    }
    return best;
  }
};

}  // namespace ewa
