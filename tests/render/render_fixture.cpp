// Shared set-up for renderer tests: context, shaders, renderer; small volume builders.
#include "render_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "ci_skip.h"
#include "gl/buffer.h"
#include "gl/gl_error.h"

namespace ewa::test {

std::unique_ptr<platform::GlContext>& RenderFixture::context() {
  static std::unique_ptr<platform::GlContext> c;
  return c;
}
std::unique_ptr<SplatRenderer>& RenderFixture::renderer() {
  static std::unique_ptr<SplatRenderer> r;
  return r;
}
std::string& RenderFixture::skipReason() {
  static std::string s;
  return s;
}
bool& RenderFixture::defaultLaggedTermination() {
  static bool lagged = false;
  return lagged;
}

void RenderFixture::SetUpTestSuite() {
  try {
    // OSMesa (llvmpipe) by default; EWA_TEST_BACKEND=egl (or EWAVIEW_BACKEND=egl, which the
    // programs the CLI tests start follow too) runs the suite on a GPU machine.
    const char* name = std::getenv("EWA_TEST_BACKEND");
    const auto backend = platform::parseHeadlessBackend(
        name && *name ? std::string(name) : platform::defaultHeadlessBackend());
    context() = platform::createHeadlessContext(backend, 16, 16);
    renderer() = std::make_unique<SplatRenderer>(gl::ShaderLibrary());
    defaultLaggedTermination() = renderer()->laggedTermination();
  } catch (const std::exception& e) {
    skipReason() = e.what();
  }
}

void RenderFixture::TearDownTestSuite() {
  renderer().reset();
  context().reset();
}

void RenderFixture::SetUp() {
  if (!renderer()) {
    EWA_SKIP_UNLESS_CI() << "no OpenGL 4.5 context: " << skipReason();
  }
  context()->makeCurrent();
  renderer()->setPointSizeLimit(1e9f);
  renderer()->setLaggedTermination(defaultLaggedTermination());  // the context's default
  // The GPU partition, which Auto leaves unused on llvmpipe: the renderer tests hold it (the
  // command-line tests draw with Auto's choice).
  renderer()->setPartition(PartitionMode::Gpu);
}

Volume makeVolume(int nx, int ny, int nz, glm::dvec3 spacing,
                  const std::function<bool(int, int, int)>& pred) {
  std::vector<uint8_t> bytes(size_t(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) bytes[i + nx * (j + size_t(ny) * k)] = pred(i, j, k) ? 200 : 0;
  return Volume({nx, ny, nz}, spacing, glm::dvec3(0.0), ScalarType::UInt8, std::move(bytes));
}

Volume floatVolume(int n, const std::function<float(int, int, int)>& value) {
  std::vector<uint8_t> bytes(size_t(n) * n * n * 4);
  float* v = reinterpret_cast<float*>(bytes.data());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) v[i + n * (j + size_t(n) * k)] = value(i, j, k);
  return Volume({n, n, n}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::Float32, std::move(bytes));
}

TransferFunction whiteTf(double alpha, double unit) {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {1.0, alpha}, {255.0, alpha}};
  tf.color = {{0.0, glm::dvec3(1.0)}, {255.0, glm::dvec3(1.0)}};
  tf.opacityUnitDistance = unit;
  return tf;
}

TransferFunction opaqueStepTf() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {0.4, 0.0}, {0.6, 1.0}, {1.0, 1.0}};
  tf.color = {{0.0, glm::dvec3(1.0)}, {1.0, glm::dvec3(1.0)}};
  return tf;
}

RenderSettings rasterSettings() {
  RenderSettings s;
  s.splatter = Splatter::Raster;
  return s;
}

RenderSettings paperSettings() {
  RenderSettings s = rasterSettings();
  s.classification.mode = ClassificationMode::Pre;
  s.kernelWidth = 1.0;
  s.cutoff = 4.0;
  return s;
}

LodScene::LodScene(const std::string& name, platform::UploadContext* uploads)
    : synthetic(makeSyntheticVolume(name)),
      lod(
          [this, uploads] {
            auto renderer = std::make_unique<SplatRenderer>(shaders);
            if (uploads) renderer->setWorkerUploadBytes(0);
            return renderer;
          },
          uploads) {
  lod.setVolume(synthetic.volume, buildLodVolumes(synthetic.volume));
  lod.setTransferFunction(*synthetic.transferFunction);
  camera.frame(synthetic.volume.boundsMin(), synthetic.volume.boundsMax(), {0.3, 0.4, 1.0},
               {0, 1, 0}, 1.0);
}

unsigned queryCount(unsigned target, const std::function<void()>& draw) {
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(target, query);
  draw();
  glEndQuery(target);
  GLuint count = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &count);
  glDeleteQueries(1, &query);
  return count;
}

std::vector<glm::vec4> dispatchCases(gl::Program& program, const void* cases, size_t caseBytes,
                                     size_t count) {
  gl::Buffer in = gl::Buffer::create(GLsizeiptr(count * caseBytes), cases);
  gl::Buffer out = gl::Buffer::create(GLsizeiptr(count * sizeof(glm::vec4)));
  in.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  program.setUInt("uCount", GLuint(count));
  glUseProgram(program.id());
  glDispatchCompute(GLuint(count + 63) / 64, 1, 1);
  glUseProgram(0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> got(count);
  out.getSubData(0, GLsizeiptr(got.size() * sizeof(glm::vec4)), got.data());
  gl::checkGlError("dispatchCases");
  return got;
}

void expectSameInterval(const glm::vec2& got, const RayInterval& want, const std::string& what) {
  if (want.empty()) {
    EXPECT_GT(got.x, got.y) << what;
    return;
  }
  EXPECT_NEAR(got.x, want.near, 1e-4 * std::max(1.0, std::fabs(want.near))) << what;
  EXPECT_NEAR(got.y, want.far, 1e-4 * std::max(1.0, std::fabs(want.far))) << what;
}

}  // namespace ewa::test
