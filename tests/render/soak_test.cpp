// Soak test: 2,000 small frames while settings, transfer functions, volumes, image sizes and
// whole renderers change; the number of live GL objects and the process memory stay flat.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>

#include "render_fixture.h"

namespace ewa::test {
namespace {

// Live GL objects by kind, found with glIs* over every name up to the newest one: names are
// handed out increasing, so a fresh probe buffer's name bounds them (with margin for kinds
// that have their own counters).
struct GlObjectCount {
  int buffers = 0, textures = 0, framebuffers = 0, vertexArrays = 0, programs = 0, shaders = 0;
  bool operator==(const GlObjectCount& o) const {
    return buffers == o.buffers && textures == o.textures && framebuffers == o.framebuffers &&
           vertexArrays == o.vertexArrays && programs == o.programs && shaders == o.shaders;
  }
};

std::ostream& operator<<(std::ostream& out, const GlObjectCount& c) {
  return out << c.buffers << " buffers, " << c.textures << " textures, " << c.framebuffers
             << " framebuffers, " << c.vertexArrays << " vertex arrays, " << c.programs
             << " programs, " << c.shaders << " shaders";
}

GLuint newestName() {
  GLuint ids[4] = {0, 0, 0, 0};
  glCreateBuffers(1, &ids[0]);
  glCreateTextures(GL_TEXTURE_2D, 1, &ids[1]);
  glCreateFramebuffers(1, &ids[2]);
  glCreateVertexArrays(1, &ids[3]);
  const GLuint newest = std::max({ids[0], ids[1], ids[2], ids[3]});
  glDeleteBuffers(1, &ids[0]);
  glDeleteTextures(1, &ids[1]);
  glDeleteFramebuffers(1, &ids[2]);
  glDeleteVertexArrays(1, &ids[3]);
  const GLuint program = glCreateProgram();
  glDeleteProgram(program);
  return std::max(newest, program);
}

GlObjectCount countGlObjects() {
  GlObjectCount c;
  const GLuint last = newestName() + 64;
  for (GLuint id = 1; id <= last; ++id) {
    c.buffers += glIsBuffer(id) == GL_TRUE;
    c.textures += glIsTexture(id) == GL_TRUE;
    c.framebuffers += glIsFramebuffer(id) == GL_TRUE;
    c.vertexArrays += glIsVertexArray(id) == GL_TRUE;
    c.programs += glIsProgram(id) == GL_TRUE;
    c.shaders += glIsShader(id) == GL_TRUE;
  }
  return c;
}

// Resident set size in KiB (/proc/self/statm counts pages).
long residentKiB() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

class Soak : public RenderFixture {};

TEST_F(Soak, ObjectCountSeesCreatedAndDeletedObjects) {
  const GlObjectCount before = countGlObjects();
  GLuint buffers[5], textures[3];
  glCreateBuffers(5, buffers);
  glCreateTextures(GL_TEXTURE_2D, 3, textures);
  const GlObjectCount during = countGlObjects();
  EXPECT_EQ(during.buffers, before.buffers + 5);
  EXPECT_EQ(during.textures, before.textures + 3);
  glDeleteBuffers(5, buffers);
  glDeleteTextures(3, textures);
  EXPECT_EQ(countGlObjects(), before);
}

TEST_F(Soak, TwoThousandFramesLeakNoGlObjectsAndNoMemory) {
  const gl::ShaderLibrary shaders;
  auto own = std::make_unique<SplatRenderer>(shaders);
  const Volume volumes[] = {
      makeVolume(6, 6, 6, glm::dvec3(1.0),
                 [](int i, int j, int k) { return (i + j + k) % 2 == 0; }),
      makeVolume(5, 7, 3, glm::dvec3(0.5, 1.0, 2.0), [](int i, int, int) { return i > 1; }),
      makeVolume(1, 1, 1, glm::dvec3(1.0), [](int, int, int) { return true; }),
  };
  const TransferFunction tfs[] = {whiteTf(0.3, 1.0), whiteTf(0.9, 0.5), whiteTf(0.0, 1.0)};
  const FilterMode filters[] = {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain};
  const int kFrames = 2000, kWarmUp = 300;
  GlObjectCount afterWarmUp;
  long rssAfterWarmUp = 0, rssSteadyStart = 0;
  // The last renderer is made at frame 1599; from here to the end nothing is recreated, so any
  // growth in this stretch is a per-frame leak, not Mesa compiling a new renderer's shaders.
  const int kSteadyStart = 1650;
  for (int frame = 0; frame < kFrames; ++frame) {
    if (frame % 400 == 399 && frame + 1 < kFrames)
      own = std::make_unique<SplatRenderer>(shaders);  // a new renderer
    if (frame % 50 == 0 || frame % 400 == 399) own->setVolume(volumes[(frame / 50) % 3]);
    if (frame % 7 == 0 || frame % 400 == 399) own->setTransferFunction(tfs[(frame / 7) % 3]);
    RenderSettings s;
    s.filter = filters[frame % 3];
    s.mode = frame % 5 == 0 ? RenderMode::XRay : RenderMode::Composite;
    s.cutoff = 2.0 + frame % 4;
    s.slabThickness = 0.5 + (frame % 3);
    Camera cam;
    cam.focalPoint = glm::dvec3(2.5);
    cam.position = cam.focalPoint +
                   glm::dvec3(20.0 * std::sin(frame * 0.1), 3.0, 20.0 * std::cos(frame * 0.1));
    cam.orthographic = frame % 11 == 0;
    const int size = 16 + frame % 3;  // new render targets every frame
    own->render(cam, s, size, 32 - size);
    if (frame % 97 == 0) (void)own->readImage();
    if (frame == kSteadyStart) rssSteadyStart = residentKiB();
    if (frame + 1 == kWarmUp) {
      afterWarmUp = countGlObjects();
      rssAfterWarmUp = residentKiB();
    }
  }
  // The same renderer count (one) and the same kinds of objects as after the warm-up.
  const GlObjectCount atEnd = countGlObjects();
  EXPECT_EQ(atEnd, afterWarmUp) << "after warm-up: " << afterWarmUp << "; at the end: " << atEnd;
  EXPECT_GT(atEnd.programs, 0);
  const long rssAtEnd = residentKiB();
  std::cout << "soak: " << atEnd << " live; RSS " << rssAfterWarmUp << " KiB after " << kWarmUp
            << " frames, " << rssAtEnd << " KiB after " << kFrames << "\n";
  // Mesa's JIT and shader caches grow with each new renderer (0.8 to 1.8 MiB each on llvmpipe,
  // four new renderers here), so the whole run gets a budget of 8 MiB, and the 350 frames after
  // the last new renderer must stay within 512 KiB: a leak of 1.5 KiB a frame would not.
  EXPECT_LT(rssAtEnd - rssAfterWarmUp, 8 * 1024)
      << "resident memory grew by " << rssAtEnd - rssAfterWarmUp << " KiB";
  EXPECT_LT(rssAtEnd - rssSteadyStart, 512)
      << "resident memory grew by " << rssAtEnd - rssSteadyStart << " KiB in the last "
      << kFrames - kSteadyStart << " frames";
  // Dropping the renderer frees its objects: fewer programs than before.
  own.reset();
  const GlObjectCount afterReset = countGlObjects();
  EXPECT_LT(afterReset.programs, atEnd.programs);
  EXPECT_LT(afterReset.buffers, atEnd.buffers);
}

}  // namespace
}  // namespace ewa::test
