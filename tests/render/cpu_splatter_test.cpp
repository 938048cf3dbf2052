// The CPU splatter (--splatter cpu) against the rasterized path: the same picture on synthetic
// scenes, pre- and post-classified (4, 2 and 1 samples a slab, unshaded or lit by voxel, ray or
// field normals), front to back and back to front, X-ray and MIP, perspective and orthographic,
// every filter, a crop box and clipping plane, early termination; a deliberately wrong footprint
// (the weak-perspective Jacobian of the volume's centre for every splat) or slab split (shares
// at each kernel's centre depth) fails the same tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "cli_run.h"
#include "core/image_metrics.h"
#include "core/synthetic_volume.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "render_fixture.h"

namespace ewa::test {
namespace {

// The tolerance the CPU picture keeps to the rasterized one (8-bit RGB over a black
// background): the largest channel difference, the mean over the covered pixels and SSIM.
// The rasterizer's slabs sum in half floats, its transfer function is a texture and it marks
// opaque pixels every few slabs where the CPU stops each pixel at its slab.
constexpr int kMaxLevels = 4;
constexpr double kMeanLevels = 1.0;
constexpr double kMinSsim = 0.99;

struct Agreement {
  int worst = 0;
  double mean = 0.0;
  double ssim = 0.0;
  bool within() const { return worst <= kMaxLevels && mean <= kMeanLevels && ssim >= kMinSsim; }
};

FloatImage floatImage(const Image8& image) {
  FloatImage out(image.width, image.height, image.channels);
  for (size_t i = 0; i < image.pixels.size(); ++i) out.values[i] = float(image.pixels[i]);
  return out;
}

Agreement agreement(const Image8& a, const Image8& b) {
  Agreement g;
  g.worst = maxDifference(a, b);
  g.mean = compareCovered(a, b, backgroundRgb8(0, 0, 0), 255).mean;
  g.ssim = structuralSimilarity(floatImage(a), floatImage(b), 255.0);
  return g;
}

// A camera looking at the volume's centre from `direction`, `distance` of its diagonals away.
Camera viewOf(const Volume& v, glm::dvec3 direction, double distance, bool orthographic) {
  const glm::dvec3 size =
      glm::dvec3(v.dims()[0] - 1, v.dims()[1] - 1, v.dims()[2] - 1) * v.spacing();
  Camera cam;
  cam.focalPoint = v.origin() + 0.5 * size;
  cam.position = cam.focalPoint + glm::normalize(direction) * (distance * glm::length(size));
  cam.viewAngleDeg = 30.0;
  cam.orthographic = orthographic;
  return cam;
}

class CpuSplatterTest : public RenderFixture {
 protected:
  // Pre-classified, rasterized at the picture's pixels (no coarser slab images), as the CPU
  // draws each slab.
  static RenderSettings preSettings() {
    RenderSettings s = rasterSettings();
    s.classification.mode = ClassificationMode::Pre;
    s.coarseSlabs = false;
    return s;
  }

  // Post-classified as the CPU draws it: at the picture's pixels, slab images of floats (the
  // rasterizer's half floats part from the CPU's float sums by a few levels more).
  static RenderSettings postSettings() {
    RenderSettings s = rasterSettings();
    s.coarseSlabs = false;
    s.slabPrecision = SlabPrecision::Float;
    return s;
  }

  // The rasterized and the CPU picture of `volume` under `settings` from `cam`.
  std::pair<Image8, Image8> draw(const Volume& volume, const TransferFunction& tf,
                                 RenderSettings settings, const Camera& cam, int width,
                                 int height) {
    SplatRenderer& r = *renderer();
    r.setVolume(volume);
    r.setTransferFunction(tf);
    r.setPartition(PartitionMode::Cpu);
    settings.splatter = Splatter::Raster;
    r.render(cam, settings, width, height);
    const Image8 raster = r.readImage();
    EXPECT_FALSE(r.stats().cpu);
    settings.splatter = Splatter::Cpu;
    r.render(cam, settings, width, height);
    EXPECT_TRUE(r.stats().cpu) << r.stats().note;
    EXPECT_EQ(r.stats().note, "");
    return {raster, r.readImage()};
  }

  // Expects the CPU picture within the tolerance of the rasterized one (and not empty).
  void expectAgrees(const std::string& name, const Volume& volume, const TransferFunction& tf,
                    const RenderSettings& settings, const Camera& cam, int width = 96,
                    int height = 80) {
    SCOPED_TRACE(name);
    const auto [raster, cpu] = draw(volume, tf, settings, cam, width, height);
    const Agreement g = agreement(cpu, raster);
    EXPECT_GT(meanValue(raster), 3.0) << "the picture should not be empty";
    EXPECT_TRUE(g.within()) << "max " << g.worst << " levels, mean " << g.mean << ", SSIM "
                            << g.ssim;
    std::printf("[ %s ] max %d levels, mean %.3f, SSIM %.5f\n", name.c_str(), g.worst, g.mean,
                g.ssim);
    if (!g.within()) {
      const std::string out = testOutputDir() + "/cpu_splatter_" + name;
      writePng(out + ".actual.png", cpu);
      writePng(out + ".raster.png", raster);
      ADD_FAILURE() << "pictures written to " << out << ".{actual,raster}.png";
    }
  }
};

TEST_F(CpuSplatterTest, SphereAgreesWithTheRasterizerInEveryFilterAndProjection) {
  const SyntheticVolume sphere = makeSyntheticVolume("sphere:32");
  for (FilterMode filter : {FilterMode::Ewa, FilterMode::Swan, FilterMode::Plain}) {
    for (bool ortho : {false, true}) {
      RenderSettings s = preSettings();
      s.filter = filter;
      const Camera cam = viewOf(sphere.volume, {0.3, 0.4, 1.0}, 1.6, ortho);
      expectAgrees(std::string("sphere_") + filterModeName(filter) + (ortho ? "_ortho" : "_persp"),
                   sphere.volume, *sphere.transferFunction, s, cam);
    }
  }
}

TEST_F(CpuSplatterTest, MarschnerLobbAndBoxAgree) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  expectAgrees("marschner_lobb", ml.volume, *ml.transferFunction, preSettings(),
               viewOf(ml.volume, {0.5, 0.7, 1.0}, 1.4, false));
  const SyntheticVolume box = makeSyntheticVolume("box:24");
  expectAgrees("box_ortho", box.volume, *box.transferFunction, preSettings(),
               viewOf(box.volume, {0.0, 0.0, 1.0}, 1.5, true));
  // The paper's kernels (width 1, cutoff 4) and an uncut depth profile.
  RenderSettings paper = paperSettings();
  paper.coarseSlabs = false;
  paper.depthCutoff = INFINITY;
  expectAgrees("box_paper", box.volume, *box.transferFunction, paper,
               viewOf(box.volume, {0.2, -0.3, 1.0}, 1.2, false));
}

TEST_F(CpuSplatterTest, CropBoxAndClipPlaneAgree) {
  const SyntheticVolume sphere = makeSyntheticVolume("sphere:32");
  RenderSettings s = preSettings();
  s.clip.cropEnabled = true;
  s.clip.cropMin = {4.0, 6.0, 3.0};
  s.clip.cropMax = {22.5, 31.0, 17.5};
  ClipPlane plane;
  plane.point = {16.0, 16.0, 16.0};
  plane.normal = glm::normalize(glm::dvec3(1.0, -0.4, 0.3));
  s.clip.planes.push_back(plane);
  expectAgrees("sphere_clipped", sphere.volume, *sphere.transferFunction, s,
               viewOf(sphere.volume, {0.6, 0.3, 1.0}, 1.5, false));
}

TEST_F(CpuSplatterTest, EarlyTerminationAgrees) {
  // Dense enough that most pixels stop well before the back.
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  TransferFunction tf = *ml.transferFunction;
  for (auto& point : tf.opacity) point.alpha = std::min(1.0, point.alpha * 8.0);
  // Never and at the default opacity: the rasterizer marks opaque pixels every few slabs, the
  // CPU stops a pixel after the slab that takes it past the threshold, so at lower thresholds
  // the two part by up to (1 - threshold) of a colour (24 levels at 0.9), as the compute tiles do.
  for (double termination : {1.0, 0.99}) {
    RenderSettings s = preSettings();
    s.terminationOpacity = termination;
    expectAgrees("termination_" + std::to_string(int(termination * 100)), ml.volume, tf, s,
                 viewOf(ml.volume, {-0.4, 0.5, 1.0}, 1.3, false));
  }
}

// The weak-perspective footprint: every splat takes the Jacobian (and so the footprint's
// shape and peak) of a kernel on the view axis at the volume centre's depth, only its centre
// and depth its own. A near, wide view, where perspective matters, fails the tolerance.
TEST_F(CpuSplatterTest, WeakPerspectiveFootprintFailsTheTolerance) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  RenderSettings s = preSettings();
  Camera cam = viewOf(ml.volume, {0.5, 0.7, 1.0}, 0.9, false);
  cam.viewAngleDeg = 60.0;
  const double centreDepth = cam.distance();
  renderer()->setCpuFootprint([centreDepth](const glm::dvec3& u, const glm::dmat3& cov,
                                            const Projection& proj, const FootprintParams& p) {
    Footprint fp = computeFootprint(u, cov, proj, p);
    const Footprint axis = computeFootprint(glm::dvec3(0.0, 0.0, -centreDepth), cov, proj, p);
    fp.covariance = axis.covariance;
    fp.conic = axis.conic;
    fp.peak = axis.peak;
    fp.depthSlope = axis.depthSlope;
    fp.depthSigma = axis.depthSigma;
    return fp;
  });
  const auto [raster, wrong] = draw(ml.volume, *ml.transferFunction, s, cam, 96, 80);
  renderer()->setCpuFootprint(computeFootprint);
  const Agreement bad = agreement(wrong, raster);
  std::printf("[ weak perspective ] max %d levels, mean %.3f, SSIM %.5f\n", bad.worst, bad.mean,
              bad.ssim);
  EXPECT_FALSE(bad.within()) << "the wrong footprint should not pass";
  // The right one does, in the same view.
  const auto [raster2, right] = draw(ml.volume, *ml.transferFunction, s, cam, 96, 80);
  const Agreement good = agreement(right, raster2);
  EXPECT_TRUE(good.within()) << "max " << good.worst << ", mean " << good.mean << ", SSIM "
                             << good.ssim;
}

// The window's budgeted steps: the CPU draws the whole frame in one step, the final pass in
// bands after it; the picture is the whole frame's.
TEST_F(CpuSplatterTest, BudgetedStepsDrawTheWholeFramesPicture) {
  const SyntheticVolume sphere = makeSyntheticVolume("sphere:32");
  SplatRenderer& r = *renderer();
  r.setVolume(sphere.volume);
  r.setTransferFunction(*sphere.transferFunction);
  RenderSettings s = preSettings();
  s.splatter = Splatter::Cpu;
  const Camera cam = viewOf(sphere.volume, {0.3, 0.4, 1.0}, 1.6, false);
  r.render(cam, s, 96, 80);
  const Image8 whole = r.readImage();
  r.beginFrame(cam, s, 96, 80);
  int steps = 1;
  while (!r.stepFrame(2.0) && steps < 10000) ++steps;
  EXPECT_TRUE(r.stats().cpu);
  EXPECT_EQ(maxDifference(r.readImage(), whole), 0) << steps << " steps";
}

TEST_F(CpuSplatterTest, PostClassifiedAgreesInEverySampleCountAndOrder) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  for (int samples : {4, 2, 1}) {
    for (CompositeOrder order : {CompositeOrder::FrontToBack, CompositeOrder::BackToFront}) {
      RenderSettings s = postSettings();
      s.slabSamples = samples == 1 ? 4 : samples;
      s.slabPreintegration = samples > 1;
      s.order = order;
      const bool ortho = order == CompositeOrder::BackToFront;
      expectAgrees("post_" + std::to_string(samples) +
                       (order == CompositeOrder::FrontToBack ? "_ftb" : "_btf"),
                   ml.volume, *ml.transferFunction, s,
                   viewOf(ml.volume, {0.5, 0.7, 1.0}, 1.4, ortho));
    }
  }
}

// Shaded: lit by the splats' voxel normals summed over each slab, by the data's gradient read
// along each pixel's ray, or by the gradient of the field from the neighbouring pixels' values
// (across tile borders: 96 x 80 pixels are 6 x 5 tiles), in every sample count and order
// (field normals with one sample a slab are voxel normals). Field normals without early
// termination: the rasterizer's opaque pixels take no more kernels, so their neighbours'
// derivatives turn one-sided there, where the CPU's (and the compute tiles') pixels add the
// kernels of every slab a neighbour still takes (FieldNormalsWithTerminationAreTheTiles).
TEST_F(CpuSplatterTest, ShadedPostClassifiedAgreesWithVoxelAndRayNormals) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  for (PostNormals normals : {PostNormals::Ray, PostNormals::Voxel, PostNormals::Field}) {
    for (int samples : {4, 2, 1}) {
      for (CompositeOrder order : {CompositeOrder::FrontToBack, CompositeOrder::BackToFront}) {
        RenderSettings s = postSettings();
        s.lighting.enabled = true;
        s.lighting.specular = 0.6;
        s.postNormals = normals;
        s.slabSamples = samples == 1 ? 4 : samples;
        s.slabPreintegration = samples > 1;
        s.order = order;
        if (normals == PostNormals::Field) s.terminationOpacity = 1.0;
        const bool ortho = order == CompositeOrder::BackToFront;
        expectAgrees(
            std::string("shaded_") + postNormalsName(normals) + "_" + std::to_string(samples) +
                (order == CompositeOrder::FrontToBack ? "_ftb" : "_btf"),
            ml.volume, *ml.transferFunction, s, viewOf(ml.volume, {0.5, 0.7, 1.0}, 1.4, ortho));
      }
    }
  }
}

// Field normals with early termination: the picture of the compute tiles, whose pixels also
// add the kernels of the slabs their neighbours take (the rasterizer's opaque pixels do not, so
// its picture parts from both by tens of levels at a few pixels here).
TEST_F(CpuSplatterTest, FieldNormalsWithTerminationAreTheTiles) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  RenderSettings s = postSettings();
  s.lighting.enabled = true;
  s.postNormals = PostNormals::Field;
  s.occlusionCulling = OcclusionCulling::Off;
  const Camera cam = viewOf(ml.volume, {0.5, 0.7, 1.0}, 1.4, false);
  SplatRenderer& r = *renderer();
  r.setVolume(ml.volume);
  r.setTransferFunction(*ml.transferFunction);
  r.setPartition(PartitionMode::Cpu);
  s.splatter = Splatter::Tiles;
  r.render(cam, s, 96, 80);
  ASSERT_TRUE(r.stats().tiles) << r.stats().note;
  const Image8 tiles = r.readImage();
  s.splatter = Splatter::Cpu;
  r.render(cam, s, 96, 80);
  ASSERT_TRUE(r.stats().cpu);
  EXPECT_GT(meanValue(tiles), 3.0);
  EXPECT_LE(maxDifference(r.readImage(), tiles), 2);
}

// The light shows: the shaded CPU picture is far from the unshaded one and within the
// tolerance of the shaded rasterized one.
TEST_F(CpuSplatterTest, ShadingChangesThePicture) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  RenderSettings s = postSettings();
  const Camera cam = viewOf(ml.volume, {0.5, 0.7, 1.0}, 1.4, false);
  const auto [rasterFlat, flat] = draw(ml.volume, *ml.transferFunction, s, cam, 96, 80);
  s.lighting.enabled = true;
  const auto [raster, lit] = draw(ml.volume, *ml.transferFunction, s, cam, 96, 80);
  EXPECT_GT(maxDifference(flat, lit), 40) << "shading should show";
  EXPECT_TRUE(agreement(lit, raster).within());
}

TEST_F(CpuSplatterTest, PostClassifiedCropAndClipAgree) {
  const SyntheticVolume sphere = makeSyntheticVolume("sphere:32");
  RenderSettings s = postSettings();
  s.clip.cropEnabled = true;
  s.clip.cropMin = {4.0, 6.0, 3.0};
  s.clip.cropMax = {22.5, 31.0, 17.5};
  ClipPlane plane;
  plane.point = {16.0, 16.0, 16.0};
  plane.normal = glm::normalize(glm::dvec3(1.0, -0.4, 0.3));
  s.clip.planes.push_back(plane);
  expectAgrees("post_clipped", sphere.volume, *sphere.transferFunction, s,
               viewOf(sphere.volume, {0.6, 0.3, 1.0}, 1.5, false));
}

TEST_F(CpuSplatterTest, PreClassifiedBackToFrontAgrees) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  RenderSettings s = preSettings();
  s.order = CompositeOrder::BackToFront;
  expectAgrees("pre_btf", ml.volume, *ml.transferFunction, s,
               viewOf(ml.volume, {-0.4, 0.5, 1.0}, 1.3, false));
}

TEST_F(CpuSplatterTest, XRayAndMipAgreeClippedOrNot) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  ClipPlane plane;
  plane.point = {20.0, 20.0, 20.0};
  plane.normal = glm::normalize(glm::dvec3(1.0, 0.5, -0.3));
  for (RenderMode mode : {RenderMode::XRay, RenderMode::Mip}) {
    for (bool clipped : {false, true}) {
      RenderSettings s = rasterSettings();
      s.mode = mode;
      if (clipped) s.clip.planes.push_back(plane);
      expectAgrees(
          std::string(mode == RenderMode::XRay ? "xray" : "mip") + (clipped ? "_clipped" : ""),
          ml.volume, *ml.transferFunction, s, viewOf(ml.volume, {0.5, 0.7, 1.0}, 1.4, false));
    }
  }
}

// Shares at each kernel centre's depth (no depth slopes): the slab split goes wrong across an
// oblique footprint, and a near, wide, oblique view fails the tolerance, pre- and
// post-classified (pre-classified with a denser transfer function: there the split only
// orders the kernels' light, which shows where the slabs are nearly opaque).
TEST_F(CpuSplatterTest, WrongSlabSplitFailsTheTolerance) {
  const SyntheticVolume ml = makeSyntheticVolume("marschner-lobb:41");
  TransferFunction dense = *ml.transferFunction;
  for (auto& point : dense.opacity) point.alpha = std::min(1.0, point.alpha * 8.0);
  Camera cam = viewOf(ml.volume, {0.9, 0.7, 0.4}, 0.9, false);
  cam.viewAngleDeg = 60.0;
  for (bool post : {false, true}) {
    SCOPED_TRACE(post);
    const RenderSettings s = post ? postSettings() : preSettings();
    const TransferFunction& tf = post ? *ml.transferFunction : dense;
    renderer()->setCpuFlatDepths(true);
    const auto [raster, wrong] = draw(ml.volume, tf, s, cam, 96, 80);
    renderer()->setCpuFlatDepths(false);
    const Agreement bad = agreement(wrong, raster);
    std::printf("[ flat depths, %s ] max %d levels, mean %.3f, SSIM %.5f\n", post ? "post" : "pre",
                bad.worst, bad.mean, bad.ssim);
    EXPECT_FALSE(bad.within()) << "the wrong split should not pass";
    const auto [raster2, right] = draw(ml.volume, tf, s, cam, 96, 80);
    const Agreement good = agreement(right, raster2);
    EXPECT_TRUE(good.within()) << "max " << good.worst << ", mean " << good.mean << ", SSIM "
                               << good.ssim;
  }
}

// --splatter cpu: the frame drawn on the CPU (splatter "cpu") within the tolerance of the
// rasterized one, cropped too, and shaded with field normals.
TEST(CpuSplatterCli, SplatterCpuDrawsTheFrame) {
  const std::string dir = testOutputDir();
  const std::string common =
      "--synthetic marschner-lobb:24 --resolution 48,48 --stats --classification pre";
  const std::string crop = " --crop 0,12,0,23,0,23";
  const CliRun raster = runEwaview(common + " --splatter raster -o " + dir + "/cpu_raster.png");
  const CliRun cpu = runEwaview(common + " --splatter cpu -o " + dir + "/cpu_cpu.png");
  const CliRun croppedRaster =
      runEwaview(common + crop + " --splatter raster -o " + dir + "/cpu_crop_r.png");
  const CliRun croppedCpu =
      runEwaview(common + crop + " --splatter cpu -o " + dir + "/cpu_crop_c.png");
  const CliRun post = runEwaview(
      "--synthetic marschner-lobb:24 --resolution 48,48 --stats --splatter cpu --shading "
      "--post-normals field -o " +
      dir + "/cpu_post.png");
  for (const CliRun* run : {&raster, &cpu, &croppedRaster, &croppedCpu, &post})
    ASSERT_EQ(run->code, 0) << run->err;
  using nlohmann::json;
  EXPECT_EQ(json::parse(raster.out)["splatter"], "raster");
  EXPECT_EQ(json::parse(cpu.out)["splatter"], "cpu");
  EXPECT_EQ(json::parse(croppedCpu.out)["splatter"], "cpu");
  EXPECT_FALSE(json::parse(cpu.out).contains("note"));
  // Its records and bins: this small frame takes one pass, more than a record a splat.
  EXPECT_GT(json::parse(cpu.out)["cpu_bytes_per_splat"].get<double>(), 64.0);
  const json postStats = json::parse(post.out);
  EXPECT_EQ(postStats["splatter"], "cpu");
  EXPECT_FALSE(postStats.contains("note"));
  const auto picture = [&](const char* name) { return readPng(dir + "/" + name + ".png"); };
  EXPECT_LE(maxDifference(picture("cpu_cpu"), picture("cpu_raster")), kMaxLevels);
  EXPECT_LE(maxDifference(picture("cpu_crop_c"), picture("cpu_crop_r")), kMaxLevels);
  EXPECT_GT(maxDifference(picture("cpu_crop_c"), picture("cpu_cpu")), 40) << "the crop shows";
}

// A frame of many splats (a solid sphere of 96³ voxels: 884,736) goes in passes that hold its
// records and bins under 32 bytes a splat (one pass would take about 100), and draws the
// rasterized picture so.
TEST(CpuSplatterCli, AFrameOfManySplatsHoldsAFewBytesASplat) {
  const std::string dir = testOutputDir();
  const std::string common = "--synthetic sphere:96 --resolution 64,64 --stats";
  const CliRun raster = runEwaview(common + " --splatter raster -o " + dir + "/many_raster.png");
  const CliRun cpu = runEwaview(common + " --splatter cpu -o " + dir + "/many_cpu.png");
  for (const CliRun* run : {&raster, &cpu}) ASSERT_EQ(run->code, 0) << run->err;
  const nlohmann::json stats = nlohmann::json::parse(cpu.out);
  EXPECT_EQ(stats["splatter"], "cpu");
  EXPECT_GT(stats["splats"].get<double>(), 800000.0);
  EXPECT_LE(stats["cpu_bytes_per_splat"].get<double>(), 32.0);
  const auto picture = [&](const char* name) { return readPng(dir + "/" + name + ".png"); };
  EXPECT_LE(maxDifference(picture("many_cpu"), picture("many_raster")), kMaxLevels);
}

// ewaview-compare times the CPU splatter beside the others (cpu_ms) where it draws the frame,
// pre- and post-classified, and leaves the column empty when skipped.
TEST(CpuSplatterCli, CompareTimesTheCpuSplatter) {
  using nlohmann::json;
  const std::string tiny =
      "--no-vtk --synthetic sphere:24 --sizes 48 --repeats 1 --skip sprites,tiles,tile-ewa,"
      "shearwarp --json";
  const std::string dir = testOutputDir() + "/cpu_compare";
  const CliRun pre =
      runProgram(EWA_COMPARE_BINARY, tiny + " --classification pre --images " + dir, "compare");
  const CliRun post = runProgram(EWA_COMPARE_BINARY, tiny, "compare");
  const CliRun skipped =
      runProgram(EWA_COMPARE_BINARY,
                 "--no-vtk --synthetic sphere:24 --sizes 48 --repeats 1 --skip cpu "
                 "--classification pre --json",
                 "compare");
  for (const CliRun* run : {&pre, &post, &skipped}) ASSERT_EQ(run->code, 0) << run->err;
  const json row = json::parse(pre.out)["rows"][0];
  EXPECT_GT(row["cpu_ms"].get<double>(), 0.0) << pre.out;
  EXPECT_GT(row["cpu_bytes_per_splat"].get<double>(), 0.0) << pre.out;
  EXPECT_TRUE(row["cpu_per_vtk_cpu"].is_null());  // no VTK
  EXPECT_GT(json::parse(post.out)["rows"][0]["cpu_ms"].get<double>(), 0.0) << post.out;
  EXPECT_TRUE(json::parse(skipped.out)["rows"][0]["cpu_ms"].is_null());
  // Its picture beside the rasterized one, within the tolerance.
  EXPECT_LE(
      maxDifference(readPng(dir + "/sphere-24_48_cpu.png"), readPng(dir + "/sphere-24_48_ewa.png")),
      kMaxLevels);
}

}  // namespace
}  // namespace ewa::test
