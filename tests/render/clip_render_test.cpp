// Crop box and clipping planes in the splat renderer: the GLSL equals src/core/clip_share.cpp,
// a cropped homogeneous medium has the analytic opacity of its cropped length, and a plane
// through a ball cuts it smoothly at sub-voxel offsets (kernels are cut, not dropped whole).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "core/clip_share.h"
#include "core/volume_orientation.h"
#include "render/clip_uniforms.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

class ClipRender : public RenderFixture {};

// One case for the shader: pixel, depth Gaussian, slab bounds and flags, a kernel centre.
struct ShaderCase {
  glm::vec4 pixelMuSigma;  // pixel x, y, mu, sigma
  glm::vec4 slab;          // zNear, zFar, openNear, openFar
  glm::vec4 kernel;        // camera-space centre, reach
};

const char* const kMirrorShader = R"(// Test: clip_region.glsl evaluated for listed cases.
layout(local_size_x = 64) in;
#include "clip_region.glsl"
struct Case { vec4 pixelMuSigma; vec4 slab; vec4 kernel; };
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
uniform uint uCount;
uniform vec2 uProfile;  // the depth profile (DepthProfile)
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount) return;
  Case c = cases[i];
  vec2 kept = clippedDepths(c.pixelMuSigma.xy);
  float share = clippedSlabFraction(c.pixelMuSigma.z, c.pixelMuSigma.w, c.slab.x, c.slab.y,
                                    c.slab.z > 0.5, c.slab.w > 0.5, kept, uProfile);
  results[i] = vec4(kept, share, clipCullsKernel(c.kernel.xyz, c.kernel.w) ? 1.0 : 0.0);
}
)";

TEST_F(ClipRender, ShaderClipShareEqualsCpp) {
  // The snippets as the product embeds them, next to the test's compute shader.
  const std::filesystem::path dir = std::filesystem::path(EWA_TEST_OUT) / "clip_mirror";
  std::filesystem::create_directories(dir);
  const gl::ShaderLibrary embedded;
  for (const char* name : {"ewa_footprint.glsl", "pixel_ray.glsl", "clip_region.glsl"})
    std::ofstream(dir / name) << embedded.source(name);
  std::ofstream(dir / "clip_mirror.comp.glsl") << kMirrorShader;
  // The cut profile takes erfSeries, as the splat variant does (SplatVariant::erfSeries).
  const gl::ShaderLibrary library(dir.string());
  gl::Program approx = library.computeProgram("clip_mirror.comp.glsl");
  gl::Program series =
      library.computeProgram("clip_mirror.comp.glsl", "#define SPLAT_ERF_SERIES 1\n");

  Volume v = makeVolume(8, 8, 8, glm::dvec3(1.0, 0.8, 1.5), [](int, int, int) { return true; });
  v.setDirection(glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.5, glm::normalize(glm::dvec3(1, 2, 0)))),
                 false);
  ClipRegion region;
  region.cropEnabled = true;
  region.cropMin = {-1.0, 0.5, 1.0};
  region.cropMax = {6.0, 5.5, 9.0};
  region.planes.push_back({glm::dvec3(3, 3, 4), glm::normalize(glm::dvec3(1, -0.5, 2)), true});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int variant = 0; variant < 4; ++variant) {
    // Both projections, the depth profile uncut and cut at one sigma.
    const bool ortho = (variant & 1) != 0;
    const DepthProfile profile = depthProfile((variant & 2) ? 1.0 : double(INFINITY));
    gl::Program& program = usesErfSeries(profile) ? series : approx;
    program.setVec2("uProfile", glm::vec2(profile.erfReach, profile.scale));
    Camera cam;
    cam.focalPoint = {3, 3, 4};
    cam.position = {14, -6, 20};
    cam.orthographic = ortho;
    const Camera local = cameraInVolumeFrame(cam, v);
    const Projection proj = local.projection(64, 48);
    std::vector<HalfSpace> planes = halfSpacesInVolumeFrame(region, v);
    for (HalfSpace& h : planes) h = transformed(h, local.viewMatrix());
    const double focalDepth = glm::length(cam.position - cam.focalPoint);
    std::vector<ShaderCase> cases;
    for (int n = 0; n < 256; ++n) {
      ShaderCase c;
      const float mu = float(focalDepth + 12.0 * (unit(rng) - 0.5));
      const float zNear = float(focalDepth + 10.0 * (unit(rng) - 0.5));
      c.pixelMuSigma = glm::vec4(64 * unit(rng), 48 * unit(rng), mu, 0.3 + 2.0 * unit(rng));
      c.slab = glm::vec4(zNear, zNear + 0.5 + 3.0 * unit(rng), unit(rng) < 0.3, unit(rng) < 0.3);
      c.kernel = glm::vec4(8 * unit(rng) - 4, 8 * unit(rng) - 4,
                           -focalDepth + 8 * (unit(rng) - 0.5), 0.5 + 2 * unit(rng));
      cases.push_back(c);
    }
    setClipUniforms(program, region, v, local, proj);
    const std::vector<glm::vec4> got =
        dispatchCases(program, cases.data(), sizeof(ShaderCase), cases.size());
    int clippedShares = 0, culled = 0;
    for (size_t n = 0; n < cases.size(); ++n) {
      const ShaderCase& c = cases[n];
      const RayInterval kept = clippedDepths(planes, proj, glm::dvec2(c.pixelMuSigma));
      const double share =
          clippedSlabFraction(c.pixelMuSigma.z, c.pixelMuSigma.w, c.slab.x, c.slab.y,
                              c.slab.z > 0.5, c.slab.w > 0.5, kept, profile);
      const std::string what = (ortho ? "orthographic case " : "perspective case ") +
                               std::to_string(n) + ((variant & 2) ? ", cut profile" : "");
      expectSameInterval(glm::vec2(got[n]), kept, what);
      EXPECT_NEAR(got[n].z, share, 2e-5) << what;
      const bool cull = clipCullsKernel(planes, glm::dvec3(c.kernel), c.kernel.w);
      double margin = 1e9;
      for (const HalfSpace& h : planes)
        margin = std::min(margin, std::fabs(h.distance(glm::dvec3(c.kernel)) + c.kernel.w));
      if (margin > 1e-4) {
        EXPECT_EQ(got[n].w > 0.5, cull) << what;
      }
      clippedShares += share > 0.0 && share < 0.999;
      culled += cull;
    }
    // The cases reach the interesting parts (fewer with the cut profile: more whole or none).
    EXPECT_GT(clippedShares, (variant & 2) ? 12 : 20);
    EXPECT_GT(culled, 10);
    EXPECT_LT(culled, 240);
  }
}

// A homogeneous slab 24 x 24 x 32 voxels seen head-on from +z; the centre four pixels.
struct CentreView {
  Volume volume = makeVolume(24, 24, 32, glm::dvec3(1.0), [](int, int, int) { return true; });
  Camera camera;
  explicit CentreView(bool ortho) {
    camera.focalPoint = {11.5, 11.5, 15.5};
    camera.position = camera.focalPoint + glm::dvec3(0, 0, 60.0);
    camera.orthographic = ortho;
    camera.viewAngleDeg = 20.0;
  }
};

double centreMean(const std::vector<float>& values, int w, int h) {
  double sum = 0.0;
  for (int y = h / 2 - 1; y <= h / 2; ++y)
    for (int x = w / 2 - 1; x <= w / 2; ++x) sum += values[size_t(y) * w + x];
  return sum / 4.0;
}

double centreOpticalDepth(SplatRenderer& r, const Camera& cam, RenderSettings settings) {
  settings.mode = RenderMode::XRay;
  r.render(cam, settings, 48, 48);
  return centreMean(r.readOpticalDepth(), 48, 48);
}

double centreOpacity(SplatRenderer& r, const Camera& cam, const RenderSettings& settings) {
  r.render(cam, settings, 48, 48);
  const Image8 img = r.readImage();
  std::vector<float> gray(size_t(img.width) * img.height);
  for (size_t p = 0; p < gray.size(); ++p) gray[p] = img.pixels[p * 3] / 255.0f;
  // readImage is top row first; the centre four pixels are symmetric anyway.
  return centreMean(gray, img.width, img.height);
}

TEST_F(ClipRender, CroppedHomogeneousMediumHasOpacityOfTheCroppedLength) {
  const double tau = 0.08;  // per world unit
  const TransferFunction tf = whiteTf(1.0 - std::exp(-tau), 1.0);
  for (bool ortho : {false, true}) {
    CentreView view(ortho);
    renderer()->setVolume(view.volume);
    renderer()->setTransferFunction(tf);
    for (FilterMode f : {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain}) {
      // Box faces between voxels and on them; a tilted plane crossing the centre ray at 9.3.
      struct Crop {
        double z0, z1;
        bool tilted;
      };
      for (const Crop crop :
           {Crop{6.3, 21.8, false}, Crop{10.0, 13.25, false}, Crop{9.3, 25.6, true}}) {
        RenderSettings s;
        s.filter = f;
        s.clip.cropEnabled = true;
        s.clip.cropMin = {-50, -50, crop.tilted ? -50.0 : crop.z0};
        s.clip.cropMax = {50, 50, crop.z1};
        if (crop.tilted)
          s.clip.planes.push_back({glm::dvec3(11.5, 11.5, crop.z0),
                                   glm::dvec3(std::sin(0.5), 0.0, std::cos(0.5)), true});
        const double L = crop.z1 - crop.z0;
        const std::string what = std::string(filterModeName(f)) + (ortho ? " ortho" : " persp") +
                                 " z " + std::to_string(crop.z0) + ".." + std::to_string(crop.z1);
        EXPECT_NEAR(centreOpticalDepth(*renderer(), view.camera, s), tau * L, 0.02 * tau * L)
            << what;
        const double expected = 1.0 - std::exp(-tau * L);
        EXPECT_NEAR(centreOpacity(*renderer(), view.camera, s), expected, 0.02 * expected + 0.004)
            << what;
      }
    }
  }
}

// A plane moved through a ball in quarter voxels: the optical depth kept along the centre
// ray falls by tau / 4 at every step (cutting kernels by their centres would give steps of
// 0 and tau), and equals tau times the kept length. The crop box's face at c.z + 5 bounds the
// other end inside the ball, where the lattice of kernels is full (near the pole it thins).
TEST_F(ClipRender, PlaneThroughBallCutsSmoothlyAtSubVoxelOffsets) {
  const double R = 10.0, tau = 0.1;
  const glm::dvec3 c(16.0, 16.0, 16.0);
  const Volume ball = makeVolume(33, 33, 33, glm::dvec3(1.0), [&](int i, int j, int k) {
    return glm::length(glm::dvec3(i, j, k) - c) <= R;
  });
  renderer()->setVolume(ball);
  renderer()->setTransferFunction(whiteTf(1.0 - std::exp(-tau), 1.0));
  for (bool ortho : {false, true}) {
    Camera cam;
    cam.focalPoint = c;
    cam.position = c + glm::dvec3(0, 0, 70.0);
    cam.viewAngleDeg = 20.0;
    cam.orthographic = ortho;
    double previous = 0.0;
    for (int step = 0; step <= 8; ++step) {
      const double zp = c.z - 1.0 + 0.25 * step;
      // Pre-classified: post's slab means make the steps alternate by about 16% (0.021, 0.029).
      RenderSettings s = paperSettings();
      s.clip.cropEnabled = true;
      s.clip.cropMin = glm::dvec3(-100.0);
      s.clip.cropMax = glm::dvec3(100.0, 100.0, c.z + 5.0);
      // Keeps the near half (towards the camera at +z); tilted about y.
      s.clip.planes.push_back({glm::dvec3(c.x, c.y, zp), glm::dvec3(0.3, 0.0, 1.0), true});
      const double got = centreOpticalDepth(*renderer(), cam, s);
      const double chord = c.z + 5.0 - zp;
      EXPECT_NEAR(got, tau * chord, 0.02 * tau * chord)
          << (ortho ? "ortho" : "persp") << " step " << step;
      if (step > 0) {
        EXPECT_NEAR(previous - got, 0.25 * tau, 0.1 * 0.25 * tau)
            << (ortho ? "ortho" : "persp") << " step " << step;
      }
      previous = got;
    }
  }
}

// Crop faces parallel to the rays: pixels outside the box keep nothing, in every mode.
TEST_F(ClipRender, CropFacesAlongTheRaysCutThePictureInEveryMode) {
  CentreView view(true);
  // Not constant: MIP shows values normalized over the volume's range.
  view.volume = makeVolume(24, 24, 32, glm::dvec3(1.0),
                           [](int i, int j, int k) { return (i + j + k) % 3 != 0; });
  renderer()->setVolume(view.volume);
  renderer()->setTransferFunction(whiteTf(0.1, 1.0));
  for (RenderMode mode : {RenderMode::Composite, RenderMode::XRay, RenderMode::Mip}) {
    RenderSettings s;
    s.mode = mode;
    s.xrayMap = XRayMap::Sum;
    s.xrayScale = 0.05;
    s.clip.cropEnabled = true;
    s.clip.cropMin = {-50, -50, -50};
    s.clip.cropMax = {11.5, 50, 50};  // x <= the centre: the left half of the picture
    renderer()->render(view.camera, s, 48, 48);
    const Image8 img = renderer()->readImage();
    for (int y = 20; y < 28; ++y) {
      EXPECT_GT(img.pixels[(size_t(y) * 48 + 18) * 3], 20) << renderModeName(mode) << " row " << y;
      EXPECT_EQ(img.pixels[(size_t(y) * 48 + 30) * 3], 0) << renderModeName(mode) << " row " << y;
    }
  }
}

}  // namespace
}  // namespace ewa::test
