// The close-up setting (--close-up, the panel's "close-up" button), today the defaults: what it
// sets, what it leaves to options given beside it, and that the program draws with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/options.h"
#include "cli_run.h"
#include "image_compare.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

struct Parsed {
  ParseResult result;
  Options options;
};

Parsed parse(std::vector<const char*> args) {
  args.insert(args.begin(), "ewaview");
  Parsed p;
  p.result = parseCommandLine(int(args.size()), args.data(), &p.options);
  return p;
}

TEST(CloseUp, SetsPostClassificationAndNarrowKernels) {
  RenderSettings s;
  s.classification.mode = ClassificationMode::Pre;
  s.kernelWidth = 1.0;
  s.cutoff = 4.0;
  s.classification.surface = SurfaceCriterion::Value;
  s.slabPreintegration = false;
  s.classification.prefilter = 0.0;
  applyCloseUpSettings(&s);
  EXPECT_EQ(s.classification.mode, ClassificationMode::Post);
  EXPECT_DOUBLE_EQ(s.classification.prefilter, kDefaultPrefilter);
  EXPECT_EQ(s.classification.surface, SurfaceCriterion::None);
  EXPECT_TRUE(s.slabPreintegration);
  EXPECT_DOUBLE_EQ(s.kernelWidth, 0.7);
  EXPECT_DOUBLE_EQ(s.cutoff, 5.0);

  const Parsed p = parse({"--synthetic", "sphere:8", "--close-up"});
  ASSERT_TRUE(p.result.run);
  EXPECT_EQ(p.options.render.classification.mode, ClassificationMode::Post);
  EXPECT_DOUBLE_EQ(p.options.render.kernelWidth, 0.7);
  EXPECT_DOUBLE_EQ(p.options.render.cutoff, 5.0);
  EXPECT_TRUE(p.options.renderOptionsGiven);  // overrides the saved settings, as its options do
  // The defaults are the close-up setting...
  const Parsed plain = parse({"--synthetic", "sphere:8"});
  EXPECT_EQ(plain.options.render.classification.mode, ClassificationMode::Post);
  EXPECT_TRUE(plain.options.render.slabPreintegration);
  EXPECT_DOUBLE_EQ(plain.options.render.kernelWidth, 0.7);
  EXPECT_DOUBLE_EQ(plain.options.render.cutoff, 5.0);
  EXPECT_DOUBLE_EQ(plain.options.render.classification.prefilter, 0.04);
  // ...except with surface splats, which need pre-classification: asked for without a
  // classification they pick it, asked for with post they are a usage error.
  const Parsed surfaces = parse({"--synthetic", "sphere:8", "--surface-threshold", "100"});
  ASSERT_TRUE(surfaces.result.run);
  EXPECT_EQ(surfaces.options.render.classification.mode, ClassificationMode::Pre);
  const Parsed both =
      parse({"--synthetic", "sphere:8", "--surface-threshold", "100", "--classification", "post"});
  EXPECT_FALSE(both.result.run);
  EXPECT_EQ(both.result.exitCode, 2);
}

TEST(CloseUp, PrefilterOptionTakesItsRangeOnly) {
  const Parsed p = parse({"--synthetic", "sphere:8", "--prefilter", "0.1", "--close-up"});
  ASSERT_TRUE(p.result.run);
  EXPECT_DOUBLE_EQ(p.options.render.classification.prefilter, 0.1);
  EXPECT_TRUE(parse({"--synthetic", "sphere:8", "--prefilter", "0"}).result.run);
  for (const char* bad : {"-0.01", "0.3", "nan", "x"}) {
    const Parsed q = parse({"--synthetic", "sphere:8", "--prefilter", bad});
    EXPECT_FALSE(q.result.run) << bad;
    EXPECT_EQ(q.result.exitCode, 2) << bad;
  }
}

TEST(CloseUp, LowPassSlabSamplesAndPassesOptions) {
  // Automatic: the paper's unit variance, post-classified too (and in X-ray and MIP); a
  // variance given is taken in any mode.
  const Parsed plain = parse({"--synthetic", "sphere:8"});
  ASSERT_TRUE(plain.result.run);
  EXPECT_EQ(plain.options.render.slabSamples, 4);
  RenderSettings s = plain.options.render;
  EXPECT_DOUBLE_EQ(lowPassVariance(s), 1.0);
  s.mode = RenderMode::Mip;
  EXPECT_DOUBLE_EQ(lowPassVariance(s), 1.0);
  const Parsed pre = parse({"--synthetic", "sphere:8", "--classification", "pre"});
  EXPECT_DOUBLE_EQ(lowPassVariance(pre.options.render), 1.0);
  const Parsed given = parse({"--synthetic", "sphere:8", "--low-pass", "0.7", "--slab-samples", "2",
                              "--classification", "pre"});
  ASSERT_TRUE(given.result.run);
  EXPECT_DOUBLE_EQ(lowPassVariance(given.options.render), 0.7);
  EXPECT_EQ(given.options.render.slabSamples, 2);
  EXPECT_TRUE(given.options.renderOptionsGiven);
  EXPECT_TRUE(parse({"--synthetic", "sphere:8", "--low-pass", "auto"}).result.run);
  for (const char* bad : {"0.05", "1.5", "nan", "x", "0.5x"}) {
    const Parsed q = parse({"--synthetic", "sphere:8", "--low-pass", bad});
    EXPECT_FALSE(q.result.run) << bad;
    EXPECT_EQ(q.result.exitCode, 2) << bad;
  }
  for (const char* bad : {"3", "1", "x"}) {
    const Parsed q = parse({"--synthetic", "sphere:8", "--slab-samples", bad});
    EXPECT_FALSE(q.result.run) << bad;
    EXPECT_EQ(q.result.exitCode, 2) << bad;
  }
  // Passes a slab: auto (0) by default, 1 or 2 given; nothing else.
  EXPECT_EQ(plain.options.render.slabPasses, 0);
  for (int passes : {1, 2})
    EXPECT_EQ(parse({"--synthetic", "sphere:8", "--slab-passes", std::to_string(passes).c_str()})
                  .options.render.slabPasses,
              passes);
  EXPECT_EQ(parse({"--synthetic", "sphere:8", "--slab-passes", "auto"}).options.render.slabPasses,
            0);
  for (const char* bad : {"0", "3", "x"}) {
    const Parsed q = parse({"--synthetic", "sphere:8", "--slab-passes", bad});
    EXPECT_FALSE(q.result.run) << bad;
    EXPECT_EQ(q.result.exitCode, 2) << bad;
  }
}

TEST(CloseUp, OptionsGivenBesideItWin) {
  const Parsed p = parse({"--synthetic", "sphere:8", "--kernel-width", "0.6", "--close-up",
                          "--classification", "pre", "--slab-preintegration", "off"});
  ASSERT_TRUE(p.result.run);
  EXPECT_EQ(p.options.render.classification.mode, ClassificationMode::Pre);
  EXPECT_FALSE(p.options.render.slabPreintegration);
  EXPECT_DOUBLE_EQ(p.options.render.kernelWidth, 0.6);
  EXPECT_DOUBLE_EQ(p.options.render.cutoff, 5.0);
  // Surface splats need pre-classification: with --close-up alone that is a usage error...
  const Parsed bad = parse({"--synthetic", "sphere:8", "--close-up", "--surface-threshold", "100"});
  EXPECT_FALSE(bad.result.run);
  EXPECT_EQ(bad.result.exitCode, 2);
  // ...and fine once --classification pre is given.
  EXPECT_TRUE(parse({"--synthetic", "sphere:8", "--close-up", "--surface-threshold", "100",
                     "--classification", "pre"})
                  .result.run);
}

// The window takes the saved render settings only when no option the settings file holds is
// given: each of them, given alone, must count (--slab-resolution and --post-normals did not,
// so the window silently drew with the saved values).
TEST(SavedSettings, EachOptionTheFileHoldsCountsAsGiven) {
  EXPECT_FALSE(parse({"--synthetic", "sphere:8"}).options.renderOptionsGiven);
  EXPECT_FALSE(parse({"--synthetic", "sphere:8", "--shading"}).options.renderOptionsGiven);
  const std::vector<std::vector<const char*>> given = {{"--filter", "swan"},
                                                       {"--render-mode", "mip"},
                                                       {"--cutoff", "4"},
                                                       {"--depth-cutoff", "4"},
                                                       {"--kernel-width", "0.8"},
                                                       {"--classification", "pre"},
                                                       {"--slab-preintegration", "off"},
                                                       {"--slab-samples", "2"},
                                                       {"--low-pass", "0.7"},
                                                       {"--prefilter", "0.1"},
                                                       {"--post-normals", "voxel"},
                                                       {"--slab-thickness", "3"},
                                                       {"--slab-resolution", "full"},
                                                       {"--background", "0.1,0.2,0.3"},
                                                       {"--close-up"}};
  for (const auto& option : given) {
    std::vector<const char*> args = {"--synthetic", "sphere:8"};
    args.insert(args.end(), option.begin(), option.end());
    const Parsed p = parse(args);
    ASSERT_TRUE(p.result.run) << option[0];
    EXPECT_TRUE(p.options.renderOptionsGiven) << option[0];
  }
  EXPECT_FALSE(
      parse({"--synthetic", "sphere:8", "--slab-resolution", "full"}).options.render.coarseSlabs);
}

// The program draws the same picture with --close-up as with its four options spelt out and as
// the defaults, and a different one from the paper's setting (pre, width 1, cutoff 4).
TEST(CloseUp, ProgramDrawsTheSpeltOutSetting) {
  const std::string dir = testOutputDir();
  const std::string scene = "--synthetic marschner-lobb:24 --resolution 48,48 --stats --output ";
  const std::vector<std::string> flags = {
      "--close-up", "--classification post --slab-preintegration on --kernel-width 0.7 --cutoff 5",
      "", "--classification pre --kernel-width 1 --cutoff 4"};
  std::vector<Image8> images;
  int levels = 0;
  for (size_t i = 0; i < flags.size(); ++i) {
    const std::string png = dir + "/close_up_" + std::to_string(i) + ".png";
    const CliRun r = runEwaview(scene + png + " " + flags[i], "close_up");
    ASSERT_EQ(r.code, 0) << flags[i] << ": " << r.err;
    images.push_back(readPng(png));
    levels = std::max(levels, runToRunLevels(r.out));
  }
  ASSERT_EQ(images[0].pixels.size(), images[1].pixels.size());
  EXPECT_LE(maxDifference(images[0], images[1]), levels);
  EXPECT_LE(maxDifference(images[0], images[2]), levels);
  size_t differing = 0;
  for (size_t i = 0; i < images[0].pixels.size(); ++i)
    differing += images[0].pixels[i] != images[3].pixels[i];
  EXPECT_GT(differing, images[0].pixels.size() / 20) << "close-up drew the paper's picture";
}

}  // namespace
}  // namespace ewa::test
