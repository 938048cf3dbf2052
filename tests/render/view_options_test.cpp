// viewOptionsText (the window's "Copy view"): the options it writes read back through the
// command line as the same camera, picture size and clip region.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/scene.h"
#include "core/synthetic_volume.h"
#include "core/view_options_text.h"

namespace ewa {
namespace {

// Parses `text` after a volume, as a shell would split it (it holds no quotes or spaces).
Options parsed(const std::string& text) {
  std::vector<std::string> words{"ewaview", "--synthetic", "sphere:16", "-o", "v.png"};
  std::istringstream in(text);
  for (std::string w; in >> w;) words.push_back(w);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  Options o;
  const ParseResult r = parseCommandLine(int(argv.size()), argv.data(), &o);
  EXPECT_TRUE(r.run) << text;
  return o;
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-9 * (1.0 + std::abs(b[i])));
}

TEST(ViewOptions, ReadBackAsTheSameViewThroughTheCommandLine) {
  Camera cam;
  cam.position = {-12.5, 3.25e-3, 400.123456789};
  cam.focalPoint = {1.0 / 3.0, -2.0, 0.0};
  cam.viewUp = {0.0, -0.6, 0.8};
  cam.viewAngleDeg = 22.5;
  cam.orthographic = true;
  ClipRegion clip;
  clip.cropEnabled = true;
  clip.cropMin = {-5.0, 0.0, 1.0 / 7.0};
  clip.cropMax = {20.0, 30.0, 40.0};
  clip.planes = {{{1.0, -2.0, 3.0}, {0.0, 0.0, -1.0}, true}, {{0.0, 0.0, 0.0}, {1, 0, 0}, false}};
  const std::string text = viewOptionsText(cam, {640, 360}, clip);
  EXPECT_EQ(text.find("-0,"), std::string::npos) << text;

  const Options o = parsed(text);
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 360);
  const Camera back = initialCamera(makeSyntheticVolume("sphere:16").volume, o);
  expectNear(back.position, cam.position);
  expectNear(back.focalPoint, cam.focalPoint);
  expectNear(back.viewUp, cam.viewUp);
  EXPECT_NEAR(back.viewAngleDeg, 22.5, 1e-12);
  EXPECT_TRUE(back.orthographic);
  ASSERT_TRUE(o.render.clip.cropEnabled);
  expectNear(o.render.clip.cropMin, clip.cropMin);
  expectNear(o.render.clip.cropMax, clip.cropMax);
  ASSERT_EQ(o.render.clip.planes.size(), 1u);  // the switched-off plane is left out
  expectNear(o.render.clip.planes[0].point, clip.planes[0].point);
  expectNear(o.render.clip.planes[0].normal, clip.planes[0].normal);

  // Pasted after one's own view options, the copied ones count (the last of each).
  const Options pasted =
      parsed("--resolution 32,32 --camera-position=1,2,3 --camera-view-angle=50 " + text);
  EXPECT_EQ(pasted.width, 640);
  const Camera again = initialCamera(makeSyntheticVolume("sphere:16").volume, pasted);
  expectNear(again.position, cam.position);
  EXPECT_NEAR(again.viewAngleDeg, 22.5, 1e-12);

  // A perspective view without clipping says only the camera and the size.
  cam.orthographic = false;
  const std::string plain = viewOptionsText(cam, {100, 80}, ClipRegion{});
  EXPECT_EQ(plain.find("orthographic"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("crop"), std::string::npos) << plain;
  EXPECT_FALSE(initialCamera(makeSyntheticVolume("sphere:16").volume, parsed(plain)).orthographic);
}

}  // namespace
}  // namespace ewa
