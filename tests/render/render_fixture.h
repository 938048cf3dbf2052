// Shared set-up for renderer tests: one OSMesa context and splat renderer per test suite.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/clip_region.h"
#include "core/synthetic_volume.h"
#include "gl/shader_library.h"
#include "platform/headless_context.h"
#include "render/lod_renderer.h"
#include "render/splat_renderer.h"

namespace ewa::test {

class RenderFixture : public ::testing::Test {
 protected:
  static void SetUpTestSuite();
  static void TearDownTestSuite();
  void SetUp() override;

  static std::unique_ptr<platform::GlContext>& context();
  static std::unique_ptr<SplatRenderer>& renderer();
  static std::string& skipReason();
  static bool& defaultLaggedTermination();  // the renderer's own, which tests may change
};

// A volume of n^3 uint8 voxels with value `inside` where pred(i,j,k) holds and 0 elsewhere.
Volume makeVolume(int nx, int ny, int nz, glm::dvec3 spacing,
                  const std::function<bool(int, int, int)>& pred);
// An n^3 float32 volume of unit spacing with value(i, j, k) at each voxel.
Volume floatVolume(int n, const std::function<float(int, int, int)>& value);
// A transfer function: value 0 transparent; values >= 1 white with opacity `alpha` per unit
// distance `unit`.
TransferFunction whiteTf(double alpha, double unit);
// For fields of 0 outside and 1 inside (shaded surfaces): values up to 0.4 transparent, from 0.6
// opaque, white.
TransferFunction opaqueStepTf();
// The default settings drawn by the rasterizer, slab by slab, as auto draws them on llvmpipe: for
// tests of what the slab passes do (steps within a budget, culling, passes, slab images, GPU
// bytes). On a GPU auto draws frames this small whole in compute tiles, in one step.
RenderSettings rasterSettings();
// The EWA paper's setting, the default before post-classification and narrow kernels were:
// pre-classified, kernels as wide as the spacing, cutoff 4, rasterized. For tests of the
// mechanisms it states (surface splats, the filters, C++ references of one splat, culling, LOD,
// slab counts).
RenderSettings paperSettings();

// Runs `program` (local size 64, uniform uCount) over `count` cases of `caseBytes` each at
// `cases` (storage buffer 0) and returns its one vec4 per case (storage buffer 1): for tests
// that hold a shader snippet equal to its C++ mirror.
std::vector<glm::vec4> dispatchCases(gl::Program& program, const void* cases, size_t caseBytes,
                                     size_t count);
// The count a GL query of `target` (GL_PRIMITIVES_GENERATED, GL_SAMPLES_PASSED, ...) gives for
// what `draw` issues, waited for.
unsigned queryCount(unsigned target, const std::function<void()>& draw);
// Expects a shader's depth interval (near, far) to equal `want` to float precision, or both
// to be empty.
void expectSameInterval(const glm::vec2& got, const RayInterval& want, const std::string& what);

// A LodRenderer of splat renderers on a synthetic volume (its coarse volumes and transfer
// function set) and a camera framing it, for the level-of-detail and refinement tests.
struct LodScene {
  // With `uploads`, every splat set of the levels' renderers is uploaded on a worker bound to it.
  explicit LodScene(const std::string& synthetic, platform::UploadContext* uploads = nullptr);
  SyntheticVolume synthetic;
  gl::ShaderLibrary shaders;
  LodRenderer lod;
  Camera camera;
};

}  // namespace ewa::test
