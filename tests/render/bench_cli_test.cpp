// ewaview-compare and ewaview --stats as a user runs them: a tiny case (synthetic volume, small
// image, one repeat, no VTK) whose output must have the documented structure and numbers that
// are positive and agree with each other. No timing is judged here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "core/splat_attributes.h"
#include "core/synthetic_volume.h"
#include "image_compare.h"
#include "io/png_io.h"
#include "render/renderer.h"

namespace ewa::test {
namespace {

using nlohmann::json;

CliRun compare(const std::string& args) {
  return runProgram(EWA_COMPARE_BINARY, args, "compare");
}

const char* kTiny = "--no-vtk --synthetic sphere:24 --sizes 48 --repeats 1";

TEST(CompareCli, JsonRowHasConsistentPositiveTimings) {
  const CliRun r = compare(std::string(kTiny) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json doc = json::parse(r.out);
  EXPECT_EQ(doc["repeats"], 1);
  // Auto leaves occlusion culling off and the partition on the CPU on software rasterizers
  // (llvmpipe), culling on and the partition on the GPU elsewhere.
  const std::string context = doc["context"].get<std::string>();
  const bool software = context.find("llvmpipe") != std::string::npos ||
                        context.find("softpipe") != std::string::npos;
  EXPECT_EQ(doc["ewa_settings"],
            std::string(
                "kernel width 0.70, cutoff 5, depth cutoff 1, slabs 2 thick, post-classification, "
                "prefilter 0.04, 4 samples a slab, half-float slab images, occlusion culling ") +
                (software ? "off" : "on") + " (auto), slab partition on the " +
                (software ? "CPU" : "GPU") + " (auto)")
      << context;
  EXPECT_NE(doc["context"].get<std::string>().find("OpenGL"), std::string::npos) << doc["context"];
  EXPECT_NE(doc["command"].get<std::string>().find("--synthetic sphere:24"), std::string::npos);
  ASSERT_EQ(doc["rows"].size(), 1u) << r.out;
  const json& row = doc["rows"][0];
  EXPECT_EQ(row["volume"], "sphere:24");
  EXPECT_EQ(row["dims"], "24x24x24");
  EXPECT_EQ(row["size"], 48);
  const double splats = row["splats"];
  EXPECT_GT(splats, 100.0);
  EXPECT_LE(row["splats_drawn"].get<double>(), splats);
  for (const char* key : {"ewa_ms", "ewa_min_ms", "splat_ms", "final_ms", "sprites_ms", "tiles_ms",
                          "tile_bin_ms", "shearwarp_ms", "ewa_per_sprites", "peak_rss_mib"})
    EXPECT_GT(row[key].get<double>(), 0.0) << key;
  EXPECT_GE(row["partition_ms"].get<double>(), 0.0);
  EXPECT_LT(row["tile_bin_ms"].get<double>(), row["tiles_ms"].get<double>());
  const double ewa = row["ewa_ms"];
  // One repeat: the median is the minimum, and the stages lie inside the full frame.
  EXPECT_DOUBLE_EQ(row["ewa_min_ms"].get<double>(), ewa);
  EXPECT_LE(row["partition_ms"].get<double>() + row["splat_ms"].get<double>() +
                row["final_ms"].get<double>(),
            ewa * 1.001);
  EXPECT_NEAR(row["ewa_per_sprites"].get<double>(), ewa / row["sprites_ms"].get<double>(),
              1e-6 * ewa);
  // --no-vtk: VTK's columns and the ratio to it are null, not zero.
  EXPECT_TRUE(row["vtk_cpu_ms"].is_null());
  EXPECT_TRUE(row["vtk_gpu_ms"].is_null());
  EXPECT_TRUE(row["ewa_per_vtk_cpu"].is_null());
}

TEST(CompareCli, KernelWidthCutoffsAndClassificationReachEwa) {
  const CliRun r =
      compare(std::string(kTiny) +
              " --kernel-width 0.55 --cutoff 5 --depth-cutoff 2.25 --slab-thickness 1 "
              "--classification post --prefilter 0.1 --slab-samples 2 --occlusion-culling off "
              "--slab-rects off --slab-resolution full --partition gpu --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json doc = json::parse(r.out);
  EXPECT_EQ(doc["ewa_settings"],
            "kernel width 0.55, cutoff 5, depth cutoff 2.25, slabs 1 thick, post-classification, "
            "prefilter 0.1, 2 samples a slab, half-float slab images, occlusion culling off, "
            "whole-image slab passes, full-resolution slabs, slab partition on the GPU");
  ASSERT_EQ(doc["rows"].size(), 1u) << r.out;
  EXPECT_GT(doc["rows"][0]["ewa_ms"].get<double>(), 0.0);
  EXPECT_EQ(doc["rows"][0]["culled_percent"].get<double>(), 0.0);
}

TEST(CompareCli, CsvAndTableHaveOneRowPerVolumeAndSize) {
  CliRun r = compare("--no-vtk --synthetic sphere:24 --sizes 32,48 --repeats 1 --csv");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(r.out);
  std::vector<std::string> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), 3u) << r.out;
  EXPECT_EQ(rows[0].rfind("volume,dims,size,splats,ewa_ms,", 0), 0u) << rows[0];
  const auto fields = [](const std::string& s) { return std::count(s.begin(), s.end(), ',') + 1; };
  EXPECT_EQ(fields(rows[1]), fields(rows[0]));
  EXPECT_EQ(rows[1].rfind("sphere:24,24x24x24,32,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[2].rfind("sphere:24,24x24x24,48,", 0), 0u) << rows[2];

  r = compare(kTiny);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("# median of 1 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ewa/vtk_cpu"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nsphere:24"), std::string::npos) << r.out;
}

TEST(CompareCli, ImagesAreWrittenForEachMethod) {
  const std::string dir = testOutputDir() + "/compare_images";
  std::filesystem::remove_all(dir);
  const CliRun r = compare(std::string(kTiny) + " --images " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* method : {"ewa", "shearwarp"}) {
    const Image8 image = readPng(dir + "/sphere-24_48_" + method + ".png");
    EXPECT_EQ(image.width, 48) << method;
    EXPECT_EQ(image.height, 48) << method;
    size_t lit = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i) lit += image.pixels[i] > 20;
    EXPECT_GT(lit, 100u) << method << ": the sphere must be visible";
  }
}

TEST(CompareCli, SkippedMethodsLeaveTheirColumnsEmpty) {
  // One pass a slab: on a GPU auto's choice would be a note.
  const CliRun r =
      compare(std::string(kTiny) + " --skip tiles,tile-ewa,shearwarp --slab-passes 1 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json doc = json::parse(r.out);
  EXPECT_EQ(doc["notes"].size(), 0u) << r.out;
  const json row = doc["rows"][0];
  for (const char* key : {"tiles_ms", "tile_bin_ms", "tile_ewa_ms", "shearwarp_ms"})
    EXPECT_TRUE(row[key].is_null()) << key << " " << row[key];
  for (const char* key : {"ewa_ms", "sprites_ms", "ewa_per_sprites"})
    EXPECT_GT(row[key].get<double>(), 0.0) << key;
  const CliRun s = compare(std::string(kTiny) + " --skip sprites --slab-passes 1 --json");
  ASSERT_EQ(s.code, 0) << s.err;
  const json otherDoc = json::parse(s.out);
  EXPECT_EQ(otherDoc["notes"].size(), 0u) << s.out;  // shear-warp draws perspective as it is
  const json other = otherDoc["rows"][0];
  EXPECT_TRUE(other["sprites_ms"].is_null());
  EXPECT_TRUE(other["ewa_per_sprites"].is_null());
  EXPECT_GT(other["tiles_ms"].get<double>(), 0.0);
  EXPECT_GT(other["shearwarp_ms"].get<double>(), 0.0);
}

TEST(CompareCli, MissingSharedDataIsSkippedWithANote) {
  const CliRun r = compare("--no-vtk --data /nonexistent --volumes engine --sizes 32 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json doc = json::parse(r.out);
  EXPECT_EQ(doc["rows"].size(), 0u);
  ASSERT_EQ(doc["notes"].size(), 1u) << r.out;  // the skip
  EXPECT_NE(doc["notes"][0].get<std::string>().find("engine skipped"), std::string::npos);
  EXPECT_NE(r.err.find("engine skipped"), std::string::npos) << r.err;
}

TEST(CompareCli, BadOptionsFailWithOneLine) {
  for (const char* args :
       {"--sizes 0", "--volumes teapot", "--repeats 0", "--csv --json", "--kernel-width 5",
        "--classification sideways", "--partition disk", "--tile-size 12", "--skip ewa"}) {
    const CliRun r = compare(args);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_GE(lineCount(r.err), 1) << args;
  }
  // NaN passes CLI11's ranges: the benchmarks' shared main refuses it first, in one line.
  for (const char* args : {"--kernel-width nan", "--cutoff=nan", "--depth-cutoff NaN"}) {
    const CliRun r = compare(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(lineCount(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("not a finite number"), std::string::npos) << r.err;
  }
}

TEST(StatsCli, OneJsonLineWithSplatsTimesAndMemory) {
  const std::string png = testOutputDir() + "/stats_sphere.png";
  const CliRun r = runEwaview("--synthetic sphere:24 --resolution 48,48 -o " + png + " --stats");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(lineCount(r.out), 1) << r.out;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["renderer"], "splat");
  EXPECT_EQ(j["width"], 48);
  EXPECT_GT(j["render_ms"].get<double>(), 0.0);
  EXPECT_GT(j["splats"].get<double>(), 100.0);
  EXPECT_LE(j["splats_drawn"].get<double>(), j["splats"].get<double>());
  EXPECT_GT(j["slabs"].get<double>(), 0.0);
  EXPECT_GT(j["slabs_drawn"].get<double>(), 0.0);
  EXPECT_LE(j["slabs_drawn"].get<double>(), j["slabs"].get<double>());
  EXPECT_GE(j["slab_entries"].get<double>(), j["splats_drawn"].get<double>());
  EXPECT_GT(j["peak_rss"].get<double>(), 1e6);
  EXPECT_TRUE(j["gpu_partition"].is_boolean()) << r.out;
  ASSERT_TRUE(j.contains("gpu_bytes"));
  if (j["gpu_bytes"].get<double>() > 0)
    EXPECT_NEAR(j["gpu_bytes_per_splat"].get<double>(),
                j["gpu_bytes"].get<double>() / j["splats"].get<double>(), 1e-6);
  else
    EXPECT_TRUE(j["gpu_bytes_per_splat"].is_null());
  // Without a picture there is no frame to report.
  EXPECT_EQ(runEwaview("--synthetic sphere:24 --stats").code, 2);
}

// The kernel's transparent-huge-page mode, as /sys shows it ("[madvise]" etc.; empty if none).
std::string hugePageModeLine() {
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(file, line);
  return line;
}

TEST(StatsCli, RunsWithHugePagesWhereTheKernelGivesThemOnRequest) {
  const std::string mode = hugePageModeLine();
  if (mode.find("[madvise]") == std::string::npos)
    GTEST_SKIP() << "transparent huge pages are not in madvise mode here: " << mode;
  const std::string png = testOutputDir() + "/stats_huge.png";
  const std::string args = "--synthetic sphere:16 --resolution 32,32 -o " + png + " --stats";
  // ewaview runs itself again with glibc.malloc.hugetlb=1 (askForHugePages) ...
  const CliRun asked = runProgram("env -u GLIBC_TUNABLES " EWA_BINARY, args, "huge");
  ASSERT_EQ(asked.code, 0) << asked.err;
  EXPECT_TRUE(json::parse(asked.out)["huge_pages"].get<bool>()) << asked.out;
  // ... beside other tunables the user set ...
  const CliRun beside =
      runProgram("env GLIBC_TUNABLES=glibc.malloc.tcache_count=7 " EWA_BINARY, args, "beside");
  ASSERT_EQ(beside.code, 0) << beside.err;
  EXPECT_TRUE(json::parse(beside.out)["huge_pages"].get<bool>()) << beside.out;
  // ... and leaves the user's own choice alone.
  const CliRun off =
      runProgram("env GLIBC_TUNABLES=glibc.malloc.hugetlb=0 " EWA_BINARY, args, "off");
  ASSERT_EQ(off.code, 0) << off.err;
  EXPECT_FALSE(json::parse(off.out)["huge_pages"].get<bool>()) << off.out;
}

TEST(StatsCli, OcclusionCullingCountsCulledDrawsAndKeepsThePicture) {
  // An opaque sphere: after its front the splats behind it are culled.
  const std::string dir = testOutputDir();
  const std::string tf = dir + "/opaque_sphere.tf.json";
  std::ofstream(tf) << R"({"opacity": [[0, 0], [0.1, 0.6], [255, 0.6]],
                           "color": [[0, 1, 1, 1], [255, 1, 0.5, 0.2]]})";
  // Pre-classified: post-classified frames are not culled (checked at the end).
  const std::string common = "--synthetic sphere:32 --tf " + tf +
                             " --resolution 64,64 --stats --classification pre --splatter raster";
  // Auto (the default) leaves culling off on llvmpipe and turns it on on a GPU: it culls
  // what one of the two below culls (checked after them).
  const CliRun automatic = runEwaview(common + " -o " + dir + "/culled_auto.png");
  ASSERT_EQ(automatic.code, 0) << automatic.err;
  const CliRun on = runEwaview(common + " -o " + dir + "/culled_on.png --occlusion-culling on");
  const CliRun off = runEwaview(common + " -o " + dir + "/culled_off.png --occlusion-culling off");
  ASSERT_EQ(on.code, 0) << on.err;
  ASSERT_EQ(off.code, 0) << off.err;
  const json a = json::parse(on.out), b = json::parse(off.out);
  EXPECT_GT(a["entries_culled"].get<double>(), 0.0);
  EXPECT_LT(a["entries_culled"].get<double>(), a["slab_entries"].get<double>());
  EXPECT_EQ(b["entries_culled"].get<double>(), 0.0);
  EXPECT_EQ(a["slab_entries"], b["slab_entries"]);
  const double culledAuto = json::parse(automatic.out)["entries_culled"].get<double>();
  EXPECT_TRUE(culledAuto == a["entries_culled"].get<double>() || culledAuto == 0.0) << culledAuto;
  const Image8 imageOn = readPng(dir + "/culled_on.png"),
               imageOff = readPng(dir + "/culled_off.png");
  EXPECT_LE(maxDifference(imageOn, imageOff), runToRunLevels(on.out))
      << "culling changed the picture";
  const CliRun post = runEwaview("--synthetic sphere:32 --tf " + tf +
                                 " --resolution 64,64 --stats --occlusion-culling on "
                                 "--splatter raster -o " +
                                 dir + "/culled_post.png");
  ASSERT_EQ(post.code, 0) << post.err;
  EXPECT_EQ(json::parse(post.out)["entries_culled"].get<double>(), 0.0);
  EXPECT_EQ(runEwaview("--synthetic sphere:8 --occlusion-culling maybe -o " + dir + "/x.png").code,
            2);
}

// --splatter tiles: the frame drawn in compute tiles (splatter "tiles"), the rasterized picture
// within a few levels, cropped too; back to front it is rasterized; a bad value is a usage
// error. The default (auto) draws one frame alone in tiles on a GPU (its first way there) and
// rasterizes it on software GL (its only way).
TEST(StatsCli, SplatterTilesDrawsTheFrameInTiles) {
  const std::string dir = testOutputDir();
  const std::string common = "--synthetic marschner-lobb:24 --resolution 48,48 --stats";
  const std::string crop = " --crop 0,12,0,23,0,23";
  const CliRun raster =
      runEwaview(common + " --splatter raster -o " + dir + "/splatter_raster.png");
  const CliRun tiles = runEwaview(common + " --splatter tiles -o " + dir + "/splatter_tiles.png");
  const CliRun croppedRaster =
      runEwaview(common + crop + " --splatter raster -o " + dir + "/splatter_crop_r.png");
  const CliRun croppedTiles =
      runEwaview(common + crop + " --splatter tiles -o " + dir + "/splatter_crop_t.png");
  const CliRun backToFront = runEwaview(
      common + " --splatter tiles --compositing back-to-front -o " + dir + "/splatter_back.png");
  const CliRun automatic = runEwaview(common + " --splatter auto -o " + dir + "/splatter_a.png");
  for (const CliRun* run :
       {&raster, &tiles, &croppedRaster, &croppedTiles, &backToFront, &automatic})
    ASSERT_EQ(run->code, 0) << run->err;
  // The GPU partition under auto: a hardware GL (whose timers auto's tiles need); on a
  // software rasterizer auto splats on the CPU.
  const bool hardware = json::parse(automatic.out)["gpu_partition"].get<bool>();
  EXPECT_EQ(json::parse(automatic.out)["splatter"], hardware ? "tiles" : "cpu");
  EXPECT_EQ(json::parse(raster.out)["splatter"], "raster");
  EXPECT_EQ(json::parse(tiles.out)["splatter"], "tiles");
  EXPECT_EQ(json::parse(croppedTiles.out)["splatter"], "tiles");
  EXPECT_EQ(json::parse(backToFront.out)["splatter"], "raster");
  const auto picture = [&](const char* name) { return readPng(dir + "/" + name + ".png"); };
  EXPECT_LE(maxDifference(picture("splatter_tiles"), picture("splatter_raster")), 4);
  EXPECT_LE(maxDifference(picture("splatter_crop_t"), picture("splatter_crop_r")), 4);
  EXPECT_GT(maxDifference(picture("splatter_crop_t"), picture("splatter_tiles")), 40)
      << "the crop should show";
  EXPECT_EQ(runEwaview("--synthetic sphere:8 --splatter compute -o " + dir + "/x.png").code, 2);
}

// A magnified sphere: its near slabs go to coarser images (slabs_coarse), --slab-resolution
// full keeps them all at the picture's resolution, a bad value is a usage error.
TEST(StatsCli, SlabResolutionReportsCoarseSlabs) {
  const std::string dir = testOutputDir();
  const std::string common =
      "--synthetic sphere:16 --resolution 160,160 --camera-position 8,-8,30 "
      "--camera-focal-point 7.5,7.5,7.5 --stats --splatter raster";
  const CliRun autoRun = runEwaview(common + " -o " + dir + "/slab_auto.png");
  const CliRun fullRun =
      runEwaview(common + " --slab-resolution full -o " + dir + "/slab_full.png");
  ASSERT_EQ(autoRun.code, 0) << autoRun.err;
  ASSERT_EQ(fullRun.code, 0) << fullRun.err;
  const json a = json::parse(autoRun.out), f = json::parse(fullRun.out);
  EXPECT_GT(a["slabs_coarse"].get<double>(), 0.0);
  EXPECT_EQ(f["slabs_coarse"].get<double>(), 0.0);
  EXPECT_EQ(a["slab_entries"], f["slab_entries"]);
  const CliRun bad = runEwaview("--synthetic sphere:8 --slab-resolution half -o " + dir + "/x.png");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--slab-resolution"), std::string::npos) << bad.err;
}

// ewaview-classify-bench: one row a volume whose splat count is what classification keeps with
// the viewer's defaults, positive times; a missing file is a one-line error naming it.
TEST(ClassifyBenchCli, RowCountsTheDefaultClassificationsSplats) {
  const CliRun r = runProgram(EWA_CLASSIFY_BENCH_BINARY,
                              "--synthetic marschner-lobb:48 --repeats 1 --threads 3", "classify");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line, name;
  long long voxels = 0;
  size_t splats = 0;
  double one = 0.0, parallel = 0.0, ratio = 0.0;
  bool found = false;
  while (std::getline(lines, line)) {
    if (line.rfind("marschner-lobb:48", 0) != 0) continue;
    std::istringstream row(line);
    found = bool(row >> name >> voxels >> splats >> one >> parallel >> ratio);
  }
  ASSERT_TRUE(found) << r.out;
  EXPECT_NE(r.out.find("3 threads"), std::string::npos) << r.out;
  const SyntheticVolume s = makeSyntheticVolume("marschner-lobb:48");
  EXPECT_EQ(voxels, s.volume.voxelCount());
  EXPECT_LT(splats, size_t(voxels));  // the transfer function leaves some out
  EXPECT_EQ(splats,
            classifySplats(s.volume, *s.transferFunction, splatClassification(RenderSettings{}))
                .splats.size());
  EXPECT_GT(one, 0.0);
  EXPECT_GT(parallel, 0.0);
  EXPECT_NEAR(ratio, parallel / one, 0.01 + 0.01 * ratio);
  const CliRun bad = runProgram(EWA_CLASSIFY_BENCH_BINARY, "/nonexistent/v.nrrd", "classify_bad");
  EXPECT_EQ(bad.code, 1);
  EXPECT_EQ(lineCount(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("/nonexistent/v.nrrd"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace ewa::test
