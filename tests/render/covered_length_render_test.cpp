// Post-classified slabs' covered length: shaders/covered_length.glsl equals
// src/core/covered_length.cpp for rays in and out of a rotated, anisotropic volume's box.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "core/covered_length.h"
#include "core/volume_orientation.h"
#include "render/clip_uniforms.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class CoveredLengthRender : public RenderFixture {};

struct ShaderCase {
  glm::vec4 pixelDepths;  // pixel x, y, stretch's near and far depth
  glm::vec4 weight;       // the kernels' summed weight there (x)
};

const char* const kMirrorShader = R"(// Test: covered_length.glsl evaluated for listed cases.
layout(local_size_x = 64) in;
#include "covered_length.glsl"
struct Case { vec4 pixelDepths; vec4 weight; };
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
uniform uint uCount;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  Case c = cases[i];
  vec2 box = boxDepths(indexRay(c.pixelDepths.xy));
  float stretch = rayStretch(c.pixelDepths.xy);
  results[i] = vec4(box, stretch,
                    coveredLength(c.pixelDepths.z, c.pixelDepths.w, box, stretch, c.weight.x));
}
)";

TEST_F(CoveredLengthRender, ShaderCoveredLengthEqualsCpp) {
  const std::filesystem::path dir = std::filesystem::path(EWA_TEST_OUT) / "covered_mirror";
  std::filesystem::create_directories(dir);
  const gl::ShaderLibrary embedded;
  for (const char* name : {"pixel_ray.glsl", "covered_length.glsl"})
    std::ofstream(dir / name) << embedded.source(name);
  std::ofstream(dir / "covered_mirror.comp.glsl") << kMirrorShader;
  gl::Program program = gl::ShaderLibrary(dir.string()).computeProgram("covered_mirror.comp.glsl");

  Volume v = makeVolume(9, 7, 12, glm::dvec3(1.0, 0.8, 1.5), [](int, int, int) { return true; });
  v.setDirection(glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.5, glm::normalize(glm::dvec3(1, 2, 0)))),
                 false);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (bool ortho : {false, true}) {
    Camera cam;
    cam.focalPoint = {4, 3, 8};
    cam.position = {18, -8, 26};
    cam.orthographic = ortho;
    const Camera local = cameraInVolumeFrame(cam, v);
    const Projection proj = local.projection(64, 48);
    const double focalDepth = glm::length(cam.position - cam.focalPoint);
    std::vector<ShaderCase> cases;
    for (int n = 0; n < 256; ++n) {
      const double a = focalDepth + 16.0 * (unit(rng) - 0.5);
      cases.push_back({glm::vec4(64 * unit(rng), 48 * unit(rng), a, a + 0.25 + 6.0 * unit(rng)),
                       glm::vec4(3.0 * unit(rng), 0, 0, 0)});
    }
    setDataBoxUniforms(program, v, local, proj);
    const std::vector<glm::vec4> got =
        dispatchCases(program, cases.data(), sizeof(ShaderCase), cases.size());
    const glm::dmat4 toIndex = cameraToIndex(v, local);
    const DataBox box = v.indexDataBox();
    int inside = 0, cut = 0, outside = 0;
    for (size_t n = 0; n < cases.size(); ++n) {
      const ShaderCase& c = cases[n];
      const glm::dvec2 pixel(c.pixelDepths.x, c.pixelDepths.y);
      const IndexRay ray = indexRay(toIndex, proj, pixel);
      const RayInterval kept = boxDepths(ray.origin, ray.direction, box);
      const double stretch = rayStretch(proj, pixel);
      const double a = c.pixelDepths.z, b = c.pixelDepths.w;
      const double want = coveredLength(a, b, kept, stretch, c.weight.x);
      const std::string what =
          (ortho ? "orthographic case " : "perspective case ") + std::to_string(n);
      expectSameInterval(glm::vec2(got[n]), kept, what);
      EXPECT_NEAR(got[n].z, stretch, 1e-5) << what;
      // Depths are float in the shader: a face within 1e-3 of the stretch's ends may fall
      // either way.
      const bool nearEdge = std::fabs(kept.near - a) < 1e-3 || std::fabs(kept.near - b) < 1e-3 ||
                            std::fabs(kept.far - a) < 1e-3 || std::fabs(kept.far - b) < 1e-3;
      if (!nearEdge) {
        EXPECT_NEAR(got[n].w, want, 1e-3 * std::max(1.0, want)) << what;
      }
      if (kept.empty() || b <= kept.near || a >= kept.far)
        ++outside;
      else if (a >= kept.near && b <= kept.far)
        ++inside;
      else
        ++cut;
    }
    // The cases reach every kind of stretch.
    EXPECT_GT(inside, 10);
    EXPECT_GT(cut, 10);
    EXPECT_GT(outside, 10);
  }
}

}  // namespace
}  // namespace ewa::test
