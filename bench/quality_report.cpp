// Markdown table and montage of the filter-quality measurements.
#include "bench/quality_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/image_convert.h"

namespace ewa {

namespace {

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string row(const SceneQuality& s, const ModeResult& m, bool isReference, bool anisotropic) {
  const std::string dash = "—";
  std::string r = "| " + s.scene.spec + " | " + m.name + " | ";
  if (isReference) {
    r += dash + " | " + dash + " | " + dash + " | " + dash + " | ";
  } else {
    r += format("%.4f", m.rmseAll) + " | " + format("%.1f", m.psnrAll) + " | " +
         format("%.4f", m.rmseBeyond) + " | " + format("%.1f", m.psnrBeyond) + " | ";
  }
  r += (m.flicker >= 0 ? format("%.4f", m.flicker) : dash) + " | ";
  r += anisotropic && !isReference ? format("%.2f", m.contrast) + " | " + format("%.2f", m.gain)
                                   : dash + " | " + dash;
  return r + " |\n";
}

// Copies `tile` into `out` with its top-left corner at (x0, y0).
void paste(FloatImage* out, const FloatImage& tile, int x0, int y0) {
  for (int y = 0; y < tile.height; ++y)
    for (int x = 0; x < tile.width; ++x)
      for (int c = 0; c < 3; ++c)
        out->at(x0 + x, y0 + y, c) = tile.at(x, y, std::min(c, tile.channels - 1));
}

FloatImage regionMap(const SceneQuality& s) {
  const SheetRegions& r = s.regions;
  const FloatImage lum = luminanceOf(s.reference.image);
  FloatImage out(r.width, r.height, 3);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t p = size_t(y) * r.width + x;
      const float g = 0.4f * lum.at(x, y);
      out.at(x, y, 0) = g;
      out.at(x, y, 1) = g + (r.anisotropic[p] ? 0.45f : 0.0f);
      out.at(x, y, 2) = g + (r.beyondK[p] ? 0.45f : 0.0f);
      // The distance k: sheet pixels beyond k with a neighbour before it.
      const bool edge =
          r.beyondK[p] && ((y + 1 < r.height && r.sheet[p + r.width] && !r.beyondK[p + r.width]));
      if (edge) out.at(x, y, 0) = out.at(x, y, 1) = 1.0f, out.at(x, y, 2) = 0.0f;
    }
  return out;
}

FloatImage difference(const FloatImage& a, const FloatImage& b, double gain) {
  FloatImage out(a.width, a.height, a.channels);
  for (size_t i = 0; i < a.values.size(); ++i)
    out.values[i] = float(std::min(1.0, gain * std::abs(double(a.values[i]) - b.values[i])));
  return out;
}

}  // namespace

std::string qualityTable(const std::vector<SceneQuality>& scenes) {
  std::string t =
      "| scene | mode | RMSE | PSNR dB | RMSE >k | PSNR >k dB | flicker >k | contrast aniso | "
      "gain aniso |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const SceneQuality& s : scenes) {
    const bool aniso = maskCount(s.regions.anisotropic) > 0;
    for (const ModeResult& m : s.modes) t += row(s, m, false, aniso);
    t += row(s, s.reference, true, aniso);
  }
  return t;
}

Image8 qualityMontage(const SceneQuality& s, double gain) {
  const int n = s.reference.image.width, h = s.reference.image.height, gap = 2;
  const int cols = 1 + int(s.modes.size());
  FloatImage out(cols * n + (cols - 1) * gap, 2 * h + gap, 3, 0.5f);
  paste(&out, s.reference.image, 0, 0);
  paste(&out, regionMap(s), 0, h + gap);
  for (int i = 0; i < int(s.modes.size()); ++i) {
    const int x0 = (i + 1) * (n + gap);
    paste(&out, s.modes[size_t(i)].image, x0, 0);
    paste(&out, difference(s.modes[size_t(i)].image, s.reference.image, gain), x0, h + gap);
  }
  return toImage8(out);
}

}  // namespace ewa
