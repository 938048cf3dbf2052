// Soak test: 2,000 frames (1,000 under ASan) through every mode and path (composite both ways,
// x-ray, MIP, shading, surface splats, the quad path, many slabs, the shear-warp renderer) while
// settings, transfer functions, volumes, image sizes and whole renderers change; the number of live
// GL objects and the process memory stay flat.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "gl/gl_api.h"
#include "render/renderer_factory.h"
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

// Bytes the C heap holds for live allocations, in KiB: unlike RSS, not moved by pages the
// allocator keeps or returns, so two identical stretches of frames give the same number.
// After glFinish: llvmpipe's threads free a frame's allocations when they finish its work, so a
// heap measured while they still run depends on how busy the machine is (a CI run under load
// read +89 KiB over a cycle that measures +0 alone).
long heapInUseKiB() {
  glFinish();
  const struct mallinfo2 m = mallinfo2();
  return long((m.uordblks + m.hblkhd) / 1024);
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

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

// What the soak run went through, counted from the renderers' statistics: the test fails if a
// mode or path it claims to cover never ran.
struct SoakCoverage {
  int composite = 0, xray = 0, mip = 0, shaded = 0, backToFront = 0, surface = 0, quads = 0,
      manySlabs = 0, shearWarp = 0;
  size_t mostSlabs = 0;
};

TEST_F(Soak, TwoThousandFramesLeakNoGlObjectsAndNoMemory) {
  const gl::ShaderLibrary shaders;
  auto own = std::make_unique<SplatRenderer>(shaders);
  std::unique_ptr<Renderer> shearWarp = createRenderer(RendererKind::ShearWarp, shaders);
  // A deep rod-like volume (48 voxels of 0.5 along z, drawn in slabs of 0.5 to 2.5 voxels:
  // 20 to 100 slabs; isotropic, so that slabs as thick as a voxel along any view stay that
  // thin), a checkered cube, an anisotropic slab and a single voxel.
  const Volume volumes[] = {
      makeVolume(
          10, 10, 48, glm::dvec3(0.5),
          [](int i, int j, int) { return (i - 4.5) * (i - 4.5) + (j - 4.5) * (j - 4.5) < 20; }),
      makeVolume(6, 6, 6, glm::dvec3(1.0),
                 [](int i, int j, int k) { return (i + j + k) % 2 == 0; }),
      makeVolume(5, 7, 3, glm::dvec3(0.5, 1.0, 2.0), [](int i, int, int) { return i > 1; }),
      makeVolume(1, 1, 1, glm::dvec3(1.0), [](int, int, int) { return true; }),
  };
  const TransferFunction tfs[] = {whiteTf(0.3, 1.0), whiteTf(0.9, 0.5), whiteTf(0.05, 1.0)};
  const FilterMode filters[] = {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain};
  // Under ASan (CI's second run) 1,000 frames: the memory bounds are skipped there (below), and
  // the GL object counts and LeakSanitizer see the same paths, renderers made twice over, at
  // half the time (118 s of that run at 2,000).
  const int kFrames = kAddressSanitizer ? 1000 : 2000, kWarmUp = 300;
  GlObjectCount afterWarmUp;
  long rssAfterWarmUp = 0, heapSteadyStart = 0;
  SoakCoverage seen;
  // Every setting is a function of the frame's place in a 200-frame cycle, and the last
  // renderers are made at frame 1599: frames 1800-1999 repeat 1600-1799 exactly with the same
  // renderers, so Mesa has compiled every shader variant they need, and any growth there is a
  // per-frame leak.
  const int kCycle = 200, kSteadyStart = kFrames - kCycle;
  const auto drawFrame = [&](int frame) {
    const int p = frame % kCycle;
    if (frame % 400 == 399 && frame + 1 < kFrames) {  // new renderers
      own = std::make_unique<SplatRenderer>(shaders);
      shearWarp = createRenderer(RendererKind::ShearWarp, shaders);
    }
    const Volume& volume = volumes[(p / 50) % 4];
    if (frame % 50 == 0 || frame % 400 == 399) {
      own->setVolume(volume);
      shearWarp->setVolume(volume);
    }
    if (p % 7 == 0 || frame % 400 == 399) {
      own->setTransferFunction(tfs[(p / 7) % 3]);
      shearWarp->setTransferFunction(tfs[(p / 7) % 3]);
    }
    // The quad path (every footprint above a 2-pixel point size) in alternate stretches.
    own->setPointSizeLimit(p % 100 < 50 ? 2.0f : 1e9f);
    RenderSettings s = paperSettings();
    s.filter = filters[p % 3];
    s.mode = p % 4 == 1 ? RenderMode::XRay : p % 4 == 2 ? RenderMode::Mip : RenderMode::Composite;
    s.xrayMap = p % 8 == 1 ? XRayMap::Sum : XRayMap::Attenuation;
    s.lighting.enabled = p % 4 == 3;
    s.order = p % 6 == 0 ? CompositeOrder::BackToFront : CompositeOrder::FrontToBack;
    // Surface splats in alternate stretches of 25 frames (the splat set is rebuilt each time).
    if ((p / 25) % 2 == 1) s.classification.surface = SurfaceCriterion::Value;
    // Post-classified (the viewer's default) in every fifth frame without surface splats.
    else if (p % 5 == 4)
      s.classification.mode = ClassificationMode::Post;
    s.cutoff = 2.0 + p % 4;
    s.slabThickness = 0.5 + (p % 3);
    Camera cam;
    cam.focalPoint = 0.5 * (volume.boundsMin() + volume.boundsMax());
    const double distance = 3.0 * glm::length(volume.boundsMax() - volume.boundsMin()) + 4.0;
    // Mostly along z (through the deep volume's 48 voxels), swinging around it.
    cam.position =
        cam.focalPoint + distance * glm::dvec3(0.4 * std::sin(p * 0.1), 0.3, std::cos(p * 0.1));
    cam.orthographic = p % 11 == 0;
    const int size = 32 + p % 3;  // new render targets every frame
    own->render(cam, s, size, 64 - size);
    const RenderStats& st = own->stats();
    seen.composite += s.mode == RenderMode::Composite;
    seen.xray += s.mode == RenderMode::XRay;
    seen.mip += s.mode == RenderMode::Mip;
    seen.shaded += s.lighting.enabled && s.mode == RenderMode::Composite;
    seen.backToFront += s.order == CompositeOrder::BackToFront && s.mode == RenderMode::Composite;
    seen.surface += st.surfaceSplats > 0;
    seen.quads += st.quadPass;
    seen.manySlabs += st.slabs >= 30;
    seen.mostSlabs = std::max(seen.mostSlabs, st.slabs);
    if (p % 97 == 0) (void)own->readImage();
    if (p % 10 == 5) {  // the CPU renderer and its output texture, now and then
      shearWarp->render(cam, s, size, 64 - size);
      ++seen.shearWarp;
    }
    if (frame + 1 == kSteadyStart) heapSteadyStart = heapInUseKiB();
    if (frame + 1 == kWarmUp) {
      afterWarmUp = countGlObjects();
      rssAfterWarmUp = residentKiB();
    }
  };
  for (int frame = 0; frame < kFrames; ++frame) drawFrame(frame);
  std::printf(
      "soak: composite %d, xray %d, mip %d, shaded %d, back to front %d, with surface "
      "splats %d, quad path %d, >= 30 slabs %d (most %zu), shear-warp %d frames\n",
      seen.composite, seen.xray, seen.mip, seen.shaded, seen.backToFront, seen.surface, seen.quads,
      seen.manySlabs, seen.mostSlabs, seen.shearWarp);
  const int each = kFrames / 20;  // every path in more than one frame of 20 (2,000: 100)
  EXPECT_GT(seen.xray, each);
  EXPECT_GT(seen.mip, each);
  EXPECT_GT(seen.shaded, each);
  EXPECT_GT(seen.backToFront, each);
  EXPECT_GT(seen.surface, each);
  EXPECT_GT(seen.quads, each);
  EXPECT_GT(seen.manySlabs, each);
  // The same renderer count and the same kinds of objects as after the warm-up.
  const GlObjectCount atEnd = countGlObjects();
  EXPECT_EQ(atEnd, afterWarmUp) << "after warm-up: " << afterWarmUp << "; at the end: " << atEnd;
  EXPECT_GT(atEnd.programs, 0);
  const long rssAtEnd = residentKiB(), heapAtEnd = heapInUseKiB();
  std::cout << "soak: " << atEnd << " live; RSS " << rssAfterWarmUp << " KiB after " << kWarmUp
            << " frames, " << rssAtEnd << " KiB after " << kFrames << "; heap in use "
            << heapSteadyStart << " KiB after frame " << kSteadyStart << ", " << heapAtEnd
            << " KiB after " << kFrames << "\n";
  // AddressSanitizer keeps freed memory in quarantine, so RSS grows there; LeakSanitizer
  // checks that build for leaks instead.
  if (!kAddressSanitizer) {
    // Mesa's JIT and shader caches grow with each new renderer, most with the first ones (on
    // llvmpipe, measured after frames 399, 799, 1199 and 1599: +5.0, +2.4, +1.2, -0.9 MiB; 7.3
    // to 9.9 MiB over the run). The CPU slab partition's worker thread allocates from a malloc
    // arena of its own, which the partitions of later renderers reuse but fragment: 12.8 MiB
    // over the run with it, 9.9 with the partition built on the calling thread. With the
    // quarter-sample variants (two programs more a renderer): 11.6 MiB alone, 16.5 once under
    // the parallel test run. The whole run's resident memory gets a budget of 24 MiB; the
    // heap check below is the leak test.
    EXPECT_LT(rssAtEnd - rssAfterWarmUp, 24 * 1024)
        << "resident memory grew by " << rssAtEnd - rssAfterWarmUp << " KiB";
    // The last cycle repeats the one before with the same renderers: the heap in use must end
    // where it started (RSS varies by up to 0.9 MiB here between runs and is no leak measure).
    // Measured alone: equal to the KiB at first, -63 and -262 KiB in two runs today; with other
    // GL tests and builds loading both cores, up to +34 KiB, and once +89 before heapInUseKiB
    // waited for llvmpipe's threads (glFinish). 64 KiB: a leak of 328
    // bytes a frame (one small object a frame) still fails; LeakSanitizer checks the rest.
    // Under load the allocator's noise once read +70 KiB (a CI run beside other work); it
    // comes and goes, while a leak grows again in every repeat of the cycle: above the bound,
    // the last cycle is drawn once more and the smaller growth counts.
    long growth = heapAtEnd - heapSteadyStart;
    if (growth >= 64) {
      const long before = heapInUseKiB();
      for (int frame = kSteadyStart; frame < kFrames; ++frame) drawFrame(frame);
      const long again = heapInUseKiB() - before;
      std::cout << "soak: the heap grew by " << growth
                << " KiB; repeating the last cycle: " << again << " KiB\n";
      growth = std::min(growth, again);
    }
    EXPECT_LT(growth, 64) << "the heap in use grew by " << growth << " KiB in the last " << kCycle
                          << " frames (and in a repeat of them)";
  }
  // Dropping the renderers frees their objects: fewer programs than before.
  own.reset();
  shearWarp.reset();
  const GlObjectCount afterReset = countGlObjects();
  EXPECT_LT(afterReset.programs, atEnd.programs);
  EXPECT_LT(afterReset.buffers, atEnd.buffers);
}

}  // namespace
}  // namespace ewa::test
