// Tests of the GL layer on the headless contexts: loader, wrappers, shader library, OSMesa + EGL.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ci_skip.h"
#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/gl_error.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "platform/egl_device_choice.h"
#include "platform/glfw_window_context.h"
#include "platform/headless_context.h"

namespace ewa::platform {
// Readable test parameter in ctest's listing.
void PrintTo(HeadlessBackend backend, std::ostream* os) {
  *os << headlessBackendName(backend);
}
}  // namespace ewa::platform

namespace ewa {
namespace {

using gl::GlError;
using platform::ContextError;
using platform::GlContext;
using platform::HeadlessBackend;

constexpr int kWidth = 8;
constexpr int kHeight = 6;
// Shaders only the tests use: tests/shaders, read from disk (the product embeds shaders/ only).
const std::string kTestShaders = std::string(EWA_TEST_DIR) + "/shaders";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A scratch folder for on-disk shaders, emptied for each test that asks for it.
std::filesystem::path scratchDir(const std::string& name) {
  std::filesystem::path dir = std::filesystem::path(EWA_TEST_OUT) / "context_test" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Creates a headless context; EGL may be missing on a machine (then the test is skipped) unless
// EWA_REQUIRE_EGL=1 says it must work. OSMesa must always work.
std::unique_ptr<GlContext> makeContext(HeadlessBackend backend, std::string& skipReason) {
  try {
    return platform::createHeadlessContext(backend, kWidth, kHeight);
  } catch (const ContextError& error) {
    const char* require = std::getenv("EWA_REQUIRE_EGL");
    if (backend == HeadlessBackend::Egl && !(require && std::string(require) == "1")) {
      skipReason = std::string("EGL unavailable here: ") + error.what();
      return nullptr;
    }
    throw;
  }
}

// Draws test_fill into a kWidth x kHeight RGBA32F target and returns its pixels, bottom row
// first. With TEST_SCALE 2 and uColor (0, 0, 0.375, -1.5) every pixel must be
// (x + 0.5, y + 0.5, 0.75, -1.5) exactly: all of these are exact binary fractions.
std::vector<float> renderTestFill() {
  gl::ShaderLibrary library(kTestShaders);
  gl::Program program =
      library.program("test_fill.vert.glsl", "test_fill.frag.glsl", "#define TEST_SCALE 2.0");
  program.setVec4("uColor", glm::vec4(0.0f, 0.0f, 0.375f, -1.5f));
  gl::Texture target = gl::Texture::create2D(GL_RGBA32F, kWidth, kHeight);
  gl::Framebuffer framebuffer = gl::Framebuffer::create();
  framebuffer.attachColor(0, target);
  framebuffer.checkComplete();
  const GLfloat clear[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
  framebuffer.clearColor(0, clear);
  gl::VertexArray empty = gl::VertexArray::create();  // core profile draws need a VAO
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, kWidth, kHeight);
  glUseProgram(program.id());
  glBindVertexArray(empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<float> pixels(kWidth * kHeight * 4, 0.0f);
  target.getImage(0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)),
                  pixels.data());
  gl::checkGlError("renderTestFill");
  return pixels;
}

void expectTestFill(const std::vector<float>& pixels) {
  ASSERT_EQ(pixels.size(), size_t(kWidth * kHeight * 4));
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float* p = &pixels[(y * kWidth + x) * 4];
      SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
      EXPECT_EQ(p[0], x + 0.5f);
      EXPECT_EQ(p[1], y + 0.5f);
      EXPECT_EQ(p[2], 0.75f);
      EXPECT_EQ(p[3], -1.5f);
    }
  }
}

class HeadlessContextTest : public ::testing::TestWithParam<HeadlessBackend> {
 protected:
  void SetUp() override {
    std::string skipReason;
    context_ = makeContext(GetParam(), skipReason);
    if (!context_) {
      EWA_SKIP_UNLESS_CI() << skipReason;
    }
  }

  std::unique_ptr<GlContext> context_;
};

TEST_P(HeadlessContextTest, IsOpenGl45Core) {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(major > 4 || (major == 4 && minor >= 5)) << major << "." << minor;
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  ASSERT_NE(version, nullptr);
  EXPECT_EQ(context_->info().version, version);
  EXPECT_TRUE(context_->info().coreProfile);
  EXPECT_TRUE(contains(context_->description(), "OpenGL 4.")) << context_->description();
  std::cout << "[ context  ] " << context_->description() << "\n";
  gl::checkGlError("IsOpenGl45Core");
}

TEST_P(HeadlessContextTest, RendersExactValuesIntoRgba32fFramebuffer) {
  expectTestFill(renderTestFill());
}

TEST_P(HeadlessContextTest, ComputeProgramFillsStorageBuffer) {
  constexpr GLuint kCount = 100;
  gl::Program program = gl::ShaderLibrary(kTestShaders).computeProgram("test_fill.comp.glsl");
  program.setFloat("uScale", 0.5f);
  program.setUInt("uCount", kCount);
  gl::Buffer values = gl::Buffer::create(kCount * sizeof(float));
  values.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  glUseProgram(program.id());
  glDispatchCompute((kCount + 63) / 64, 1, 1);
  glUseProgram(0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> result(kCount, -1.0f);
  values.getSubData(0, kCount * sizeof(float), result.data());
  for (GLuint i = 0; i < kCount; ++i) EXPECT_EQ(result[i], i * 0.5f) << "index " << i;
  gl::checkGlError("ComputeProgramFillsStorageBuffer");
}

TEST_P(HeadlessContextTest, BrokenShaderNamesFileAndCompileLog) {
  // A folder per backend: ctest -j runs the backends' instances at once.
  std::filesystem::path dir = scratchDir("broken_" + std::to_string(int(GetParam())));
  writeFile(dir / "test_fill.vert.glsl",
            gl::ShaderLibrary(kTestShaders).source("test_fill.vert.glsl"));
  writeFile(dir / "broken.frag.glsl",
            "// A fragment shader with an undeclared name.\n"
            "out vec4 fragColor;\n"
            "void main() { fragColor = undeclaredThing; }\n");
  gl::ShaderLibrary library(dir.string());
  try {
    library.program("test_fill.vert.glsl", "broken.frag.glsl");
    FAIL() << "a broken shader compiled";
  } catch (const GlError& error) {
    std::string message = error.what();
    EXPECT_TRUE(contains(message, "broken.frag.glsl")) << message;
    EXPECT_TRUE(contains(message, "fragment")) << message;
    EXPECT_TRUE(contains(message, "undeclaredThing")) << message;  // from GL's info log
    // #line keeps the file's line numbers: string 0, line 3 (Mesa "0:3(..)", NVIDIA "0(3)")
    EXPECT_TRUE(contains(message, "0:3") || contains(message, "0(3)")) << message;
  }
}

TEST_P(HeadlessContextTest, ErrorInIncludedFileIsListedBySourceString) {
  std::filesystem::path dir = scratchDir("broken_include_" + std::to_string(int(GetParam())));
  writeFile(dir / "bad_snippet.glsl", "// Broken snippet.\nfloat f() { return missingName; }\n");
  writeFile(dir / "user.comp.glsl",
            "layout(local_size_x = 1) in;\n#include \"bad_snippet.glsl\"\nvoid main() {}\n");
  try {
    gl::ShaderLibrary(dir.string()).computeProgram("user.comp.glsl");
    FAIL() << "a broken include compiled";
  } catch (const GlError& error) {
    std::string message = error.what();
    EXPECT_TRUE(contains(message, "user.comp.glsl")) << message;
    // source string 1, line 2 (Mesa "1:2(..)", NVIDIA "1(2)")
    EXPECT_TRUE(contains(message, "1:2") || contains(message, "1(2)")) << message;
    EXPECT_TRUE(contains(message, "1 = bad_snippet.glsl")) << message;
  }
}

TEST_P(HeadlessContextTest, IncompleteFramebufferThrows) {
  gl::Framebuffer noAttachments = gl::Framebuffer::create();
  try {
    noAttachments.checkComplete();
    FAIL() << "a framebuffer without attachments was complete";
  } catch (const GlError& error) {
    EXPECT_TRUE(contains(error.what(), "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"))
        << error.what();
  }
  gl::Texture noStorage = gl::Texture::create(GL_TEXTURE_2D);
  gl::Framebuffer badAttachment = gl::Framebuffer::create();
  badAttachment.attachColor(0, noStorage);
  EXPECT_THROW(badAttachment.checkComplete(), GlError);
  EXPECT_THROW(gl::Framebuffer().checkComplete(), GlError);
}

TEST_P(HeadlessContextTest, MovingBufferTransfersOwnership) {
  gl::Buffer first = gl::Buffer::create(64);
  GLuint id = first.id();
  ASSERT_NE(id, 0u);
  gl::Buffer second(std::move(first));
  EXPECT_EQ(first.id(), 0u);  // NOLINT(bugprone-use-after-move): the point of the test
  EXPECT_EQ(first.size(), 0);
  EXPECT_EQ(second.id(), id);
  EXPECT_EQ(second.size(), 64);
  EXPECT_TRUE(glIsBuffer(id));
  {
    gl::Buffer third;
    third = std::move(second);
    EXPECT_EQ(second.id(), 0u);  // NOLINT(bugprone-use-after-move)
    EXPECT_EQ(third.id(), id);
  }
  EXPECT_FALSE(glIsBuffer(id));  // the last owner deleted it
  EXPECT_THROW(gl::Buffer::create(16).setSubData(8, 16, nullptr), GlError);
}

TEST_P(HeadlessContextTest, BufferReserveGrowsExactlyFirstThenByHalfAgain) {
  gl::Buffer b;
  b.reserve(100, "test buffer");  // creates it, exactly
  ASSERT_NE(b.id(), 0u);
  EXPECT_EQ(b.size(), 100);
  b.reserve(80, "test buffer");  // big enough: kept
  EXPECT_EQ(b.size(), 100);
  b.reserve(200, "test buffer");  // grows with room to settle
  EXPECT_EQ(b.size(), 300);
  gl::Buffer tiny;
  tiny.reserve(0, "test buffer");  // never empty: storage buffers need some bytes
  EXPECT_EQ(tiny.size(), 16);
}

TEST_P(HeadlessContextTest, UniformLocationsAreCachedAndMissingOnesAreMinusOne) {
  gl::Program program =
      gl::ShaderLibrary(kTestShaders).program("test_fill.vert.glsl", "test_fill.frag.glsl");
  GLint location = program.uniformLocation("uColor");
  EXPECT_GE(location, 0);
  EXPECT_EQ(program.uniformLocation("uColor"), location);
  EXPECT_EQ(program.uniformLocation("noSuchUniform"), -1);
  program.setFloat("noSuchUniform", 1.0f);  // ignored, as GL does
  gl::checkGlError("uniforms");
  gl::Program moved = std::move(program);
  EXPECT_EQ(program.id(), 0u);  // NOLINT(bugprone-use-after-move)
  EXPECT_EQ(moved.uniformLocation("uColor"), location);
}

TEST_P(HeadlessContextTest, CheckGlErrorThrowsWithLocation) {
  glEnable(0xFFFF);  // GL_INVALID_ENUM
  try {
    gl::checkGlError("the bad enable");
    FAIL() << "no GL error reported";
  } catch (const GlError& error) {
    EXPECT_TRUE(contains(error.what(), "the bad enable")) << error.what();
    EXPECT_TRUE(contains(error.what(), "GL_INVALID_ENUM")) << error.what();
  }
  EXPECT_NO_THROW(gl::checkGlError("after draining"));
}

INSTANTIATE_TEST_SUITE_P(Backends, HeadlessContextTest,
                         ::testing::Values(HeadlessBackend::OsMesa, HeadlessBackend::Egl),
                         [](const ::testing::TestParamInfo<HeadlessBackend>& info) {
                           return std::string(platform::headlessBackendName(info.param));
                         });

// OSMesa and EGL come from different libraries; both must work from one process, alive at once,
// with makeCurrent reloading the function pointers when switching.
TEST(HeadlessContexts, OsMesaAndEglInOneProcess) {
  std::string skipReason;
  auto osmesa = makeContext(HeadlessBackend::OsMesa, skipReason);
  expectTestFill(renderTestFill());
  auto egl = makeContext(HeadlessBackend::Egl, skipReason);
  if (!egl) {
    EWA_SKIP_UNLESS_CI() << skipReason;
  }
  expectTestFill(renderTestFill());
  osmesa->makeCurrent();
  expectTestFill(renderTestFill());
  egl->makeCurrent();
  expectTestFill(renderTestFill());
}

// EWAVIEW_EGL_DEVICE=N draws on device N alone; a device EGL does not list is one line naming
// the variable. A local rank (setEglLocalRank) puts its device first.
TEST(HeadlessContexts, EglDeviceByIndexAndByLocalRank) {
  std::string skipReason;
  ::setenv("EWAVIEW_EGL_DEVICE", "0", 1);
  auto first = makeContext(HeadlessBackend::Egl, skipReason);
  if (!first) {
    ::unsetenv("EWAVIEW_EGL_DEVICE");
    EWA_SKIP_UNLESS_CI() << skipReason;
  }
  EXPECT_EQ(first->backendName(), "EGL (device 0)");
  expectTestFill(renderTestFill());
  first.reset();
  ::setenv("EWAVIEW_EGL_DEVICE", "4096", 1);
  try {
    platform::createHeadlessContext(HeadlessBackend::Egl, kWidth, kHeight);
    ADD_FAILURE() << "device 4096 accepted";
  } catch (const ContextError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(contains(message, "EWAVIEW_EGL_DEVICE=4096")) << message;
    EXPECT_FALSE(contains(message, "\n")) << message;
  }
  ::unsetenv("EWAVIEW_EGL_DEVICE");
  platform::setEglLocalRank(3);
  auto ranked = platform::createHeadlessContext(HeadlessBackend::Egl, kWidth, kHeight);
  EXPECT_TRUE(contains(ranked->backendName(), "EGL (device ")) << ranked->backendName();
  expectTestFill(renderTestFill());
  platform::setEglLocalRank(-1);
}

TEST(HeadlessContexts, ParsesBackendNames) {
  EXPECT_EQ(platform::parseHeadlessBackend("osmesa"), HeadlessBackend::OsMesa);
  EXPECT_EQ(platform::parseHeadlessBackend("OSMesa"), HeadlessBackend::OsMesa);
  EXPECT_EQ(platform::parseHeadlessBackend("egl"), HeadlessBackend::Egl);
  try {
    platform::parseHeadlessBackend("vulkan");
    FAIL() << "accepted a bad backend name";
  } catch (const std::invalid_argument& error) {
    EXPECT_TRUE(contains(error.what(), "vulkan")) << error.what();
  }
}

// Runs only with a display (e.g. under xvfb-run); GLX on llvmpipe offers 4.5 core too.
TEST(GlfwWindowContext, OpensHiddenWindowWith45Core) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if (!(display && *display) && !(wayland && *wayland)) {
    EWA_SKIP_UNLESS_CI() << "no display";
  }
  platform::WindowOptions options;
  options.width = 64;
  options.height = 48;
  options.visible = false;
  platform::GlfwWindowContext window(options);
  EXPECT_TRUE(window.info().coreProfile);
  EXPECT_NE(window.window(), nullptr);
  glm::ivec2 size = window.framebufferSize();
  EXPECT_GT(size.x, 0);
  EXPECT_GT(size.y, 0);
  expectTestFill(renderTestFill());
  window.swapBuffers();
}

// ShaderLibrary text handling; needs no GL context.
TEST(ShaderLibrary, ResolvesIncludesAndPrependsVersionOnce) {
  std::filesystem::path dir = scratchDir("includes");
  writeFile(dir / "a.glsl", "float a() { return 1.0; }\n");
  writeFile(dir / "b.glsl", "#include \"a.glsl\"\nfloat b() { return a(); }\n");
  writeFile(dir / "main.frag.glsl",
            "#include \"a.glsl\"\n  # include \"b.glsl\"  // diamond\nvoid main() {}\n");
  gl::ShaderLibrary library(dir.string());
  EXPECT_EQ(library.source("main.frag.glsl"),
            "float a() { return 1.0; }\nfloat b() { return a(); }\nvoid main() {}\n");
  gl::ShaderSource stage =
      library.stageSource(gl::ShaderStage::Fragment, "main.frag.glsl", "#define X 1");
  EXPECT_EQ(stage.code.rfind("#version 450 core\n#define X 1\n#line 1 0\n", 0), 0u) << stage.code;
  EXPECT_EQ(stage.code.find("#version", 1), std::string::npos);
  EXPECT_EQ(stage.files, (std::vector<std::string>{"main.frag.glsl", "a.glsl", "b.glsl"}));
  EXPECT_TRUE(library.contains("a.glsl"));
  EXPECT_FALSE(library.contains("nope.glsl"));
}

TEST(ShaderLibrary, ReportsUnknownCyclicAndVersionedShaders) {
  std::filesystem::path dir = scratchDir("errors");
  writeFile(dir / "loop_a.glsl", "#include \"loop_b.glsl\"\n");
  writeFile(dir / "loop_b.glsl", "#include \"loop_a.glsl\"\n");
  writeFile(dir / "versioned.glsl", "#version 330\n");
  writeFile(dir / "includes_missing.glsl", "\n#include \"ghost.glsl\"\n");
  gl::ShaderLibrary library(dir.string());
  auto messageOf = [&](const std::string& name) -> std::string {
    try {
      library.source(name);
    } catch (const GlError& error) {
      return error.what();
    }
    return "(no error)";
  };
  EXPECT_TRUE(contains(messageOf("nope.glsl"), "\"nope.glsl\""));
  EXPECT_TRUE(contains(messageOf("loop_a.glsl"), "loop_a.glsl -> loop_b.glsl -> loop_a.glsl"));
  EXPECT_TRUE(contains(messageOf("versioned.glsl"), "#version"));
  std::string missing = messageOf("includes_missing.glsl");
  EXPECT_TRUE(contains(missing, "ghost.glsl") && contains(missing, "includes_missing.glsl"))
      << missing;
  EXPECT_THROW(gl::ShaderLibrary().source("no_such_shader.glsl"), GlError);
}

TEST(ShaderLibrary, EmbeddedShadersHaveNoVersionLineAndResolve) {
  gl::ShaderLibrary library;
  ASSERT_FALSE(embeddedShaders().empty());
  for (const auto& [name, text] : embeddedShaders()) {
    EXPECT_NO_THROW(library.source(name)) << name;
  }
}

}  // namespace
}  // namespace ewa
