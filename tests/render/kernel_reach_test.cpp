// Holds shaders/kernel_reach.glsl equal to src/core/kernel_reach.cpp: a compute shader evaluates
// the GLSL at sample depths and variances under every filter, projection and spacing kind.
#include "core/kernel_reach.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/gl_error.h"
#include "gl/shader_library.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class KernelReachMirror : public RenderFixture {};

// A library over a scratch folder holding the test shader (tests/shaders) and the product's
// kernel_reach.glsl (embedded), so the test includes exactly what the splat shaders include.
gl::ShaderLibrary reachLibrary() {
  const std::filesystem::path dir =
      std::filesystem::path(EWA_TEST_OUT) / "kernel_reach_test" / "shaders";
  std::filesystem::create_directories(dir);
  std::ifstream test(std::string(EWA_TEST_DIR) + "/shaders/test_kernel_reach.comp.glsl",
                     std::ios::binary);
  std::ofstream(dir / "test_kernel_reach.comp.glsl", std::ios::binary) << test.rdbuf();
  std::ofstream(dir / "kernel_reach.glsl", std::ios::binary)
      << gl::ShaderLibrary().source("kernel_reach.glsl");
  return gl::ShaderLibrary(dir.string());
}

TEST_F(KernelReachMirror, GlslEqualsCpp) {
  gl::Program program = reachLibrary().computeProgram("test_kernel_reach.comp.glsl");
  // Depths from behind the eye to far away; variances of flat to elongated kernels.
  std::vector<glm::vec2> inputs;
  for (double depth : {-3.0, 0.0, 0.4, 1.0, 7.5, 40.0, 300.0, 2500.0})
    for (double variance : {0.0, 0.04, 1.0, 6.25}) inputs.push_back(glm::vec2(depth, variance));
  const GLuint count = GLuint(inputs.size());
  gl::Buffer in = gl::Buffer::create(GLsizeiptr(count * sizeof(glm::vec2)), inputs.data());
  gl::Buffer out = gl::Buffer::create(GLsizeiptr(count * sizeof(glm::vec4)));
  size_t cases = 0;
  for (bool orthographic : {false, true})
    for (FilterMode filter : {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain})
      for (glm::dvec3 spacing : {glm::dvec3(1.0), glm::dvec3(0.5, 0.8, 2.0)})
        for (double cutoff : {1.0, 4.0, 9.0})
          for (double scale : {0.05, 3.0, 700.0})  // pixels per unit (ortho) or focal / 100
            for (double depthCutoff : {double(INFINITY), 2.25}) {
              Projection proj;
              proj.orthographic = orthographic;
              proj.pixelsPerUnit = scale;
              proj.focalPixels = scale * 100.0;
              const KernelReach k = kernelReach(proj, filter, cutoff, spacing, 0.7, depthCutoff);
              program.setFloat("uCutoff", float(k.cutoff));
              program.setFloat("uDepthCutoff", float(k.depthCutoff));
              program.setFloat("uMaxSigma", float(k.maxSigma));
              program.setFloat("uSwanSpacing", float(k.swanSpacing));
              program.setInt("uSwan", k.swan ? 1 : 0);
              program.setInt("uOrthographic", k.orthographic ? 1 : 0);
              program.setFloat("uFocalPixels", float(k.focalPixels));
              program.setFloat("uPixelsPerUnit", float(k.pixelsPerUnit));
              program.setUInt("uCount", count);
              in.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
              out.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
              glUseProgram(program.id());
              glDispatchCompute((count + 63) / 64, 1, 1);
              glUseProgram(0);
              glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
              std::vector<glm::vec4> got(count);
              out.getSubData(0, GLsizeiptr(count * sizeof(glm::vec4)), got.data());
              for (GLuint i = 0; i < count; ++i) {
                const double depth = inputs[i].x, variance = inputs[i].y;
                const double want[4] = {worldPerPixel(k, depth), reachStretch(k, depth),
                                        worldReach(k, depth), depthReach(k, variance, depth)};
                for (int c = 0; c < 4; ++c)
                  EXPECT_NEAR(got[i][c], want[c], 1e-5 * std::abs(want[c]) + 1e-7)
                      << "value " << c << " depth " << depth << " variance " << variance
                      << (orthographic ? " ortho" : " persp") << " filter " << int(filter)
                      << " cutoff " << cutoff << " scale " << scale << " depth cutoff "
                      << depthCutoff;
                ++cases;
              }
            }
  EXPECT_EQ(cases, 2u * 3u * 2u * 3u * 3u * 2u * inputs.size());
  gl::checkGlError("KernelReachMirror");
}

}  // namespace
}  // namespace ewa::test
