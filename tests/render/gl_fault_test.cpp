// GL faults and writes as a user meets them: broken shaders (compile and link), oversized
// images, an --output naming an input, and screenshots that replace files atomically.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ci_skip.h"
#include "cli_run.h"
#include "image_compare.h"

namespace ewa::test {
namespace {

namespace fs = std::filesystem;

// A per-test scratch folder under the test output folder.
fs::path scratch() {
  const fs::path dir =
      fs::path(testOutputDir()) /
      ("gl_fault_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// `timeout`: were an error missed, the window would wait for a user for ever.
CliRun ewaview(const fs::path& dir, const std::string& args) {
  return runEwaview(args, "gl_fault", 60);
}

TEST(GlFaults, ShaderCompileErrorIsOneLineWithTheGlLogAndExitOne) {
  const fs::path dir = scratch();
  const fs::path shaders =
      brokenShaders(dir, "final_composite.frag.glsl", "void main", "int broken = ;\nvoid main");
  const fs::path out = dir / "x.png";
  const CliRun r = ewaview(dir, "--synthetic sphere:8 --resolution 16,16 --shader-dir " +
                                    shaders.string() + " --output " + out.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cannot compile fragment shader"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("final_composite.frag.glsl"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("error"), std::string::npos) << "no GL log: " << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(GlFaults, ShaderLinkErrorIsOneLineWithTheGlLogAndExitOne) {
  const fs::path dir = scratch();
  // A function declared and called but never defined: compiles, fails to link.
  const fs::path shaders = brokenShaders(
      dir, "final_composite.frag.glsl", "  outColor = vec4(clamp(rgb, 0.0, 1.0), 1.0);",
      "  outColor = vec4(clamp(rgb, 0.0, 1.0), neverDefined(1.0));");
  brokenShaders(dir, "final_composite.frag.glsl", "void main",
                "float neverDefined(float x);\nvoid main");
  const CliRun r = ewaview(dir, "--synthetic sphere:8 --resolution 16,16 --shader-dir " +
                                    shaders.string() + " --output " + (dir / "x.png").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cannot link program"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("neverDefined"), std::string::npos) << "no GL log: " << r.err;
}

TEST(GlFaults, WindowWithABrokenShaderSaysSoAndExitsOne) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) EWA_SKIP_UNLESS_CI() << "no display";
  const fs::path dir = scratch();
  const fs::path shaders =
      brokenShaders(dir, "splat.frag.glsl", "void main", "int broken = ;\nvoid main");
  // `timeout`: were the error missed, the window would wait for a user for ever.
  const CliRun r =
      ewaview(dir, "--synthetic sphere:8 --resolution 64,64 --shader-dir " + shaders.string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("splat.frag.glsl"), std::string::npos) << r.err;
}

TEST(GlFaults, MissingShaderFolderIsOneLine) {
  const fs::path dir = scratch();
  const CliRun r =
      ewaview(dir, "--synthetic sphere:8 --resolution 16,16 --shader-dir " +
                       (dir / "nowhere").string() + " --output " + (dir / "x.png").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nowhere"), std::string::npos) << r.err;
}

TEST(GlFaults, OutputNamingAnInputIsRefusedAndTheInputKept) {
  const fs::path dir = scratch();
  const fs::path volume = dir / "v.nrrd";
  {
    std::ofstream f(volume, std::ios::binary);
    f << "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n";
    f.write("\x00\x10\x20\x30\x40\x50\x60\x70", 8);
  }
  const std::string before = readWholeFile(volume);
  CliRun r = ewaview(dir, volume.string() + " --resolution 16,16 --output " + volume.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("refusing to overwrite"), std::string::npos) << r.err;
  // Another spelling of the same file is caught too.
  r = ewaview(dir,
              volume.string() + " --resolution 16,16 --output " + (dir / "." / "v.nrrd").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(readWholeFile(volume), before);
  // A transfer-function input as well.
  const fs::path tf = dir / "t.tf.json";
  std::ofstream(tf) << R"({"opacity": [[0, 0], [255, 1]]})";
  r = ewaview(dir, volume.string() + " --tf " + tf.string() + " --resolution 16,16 --output " +
                       tf.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(readWholeFile(tf).find("opacity"), std::string::npos);
}

// The files a volume is read from, not only the one named: a stack's slices, a header's data.
TEST(GlFaults, OutputNamingASliceOrDataFileOfTheInputIsRefused) {
  const fs::path dir = scratch();
  const fs::path slices = dir / "slices";
  fs::create_directories(slices);
  Image8 slice;
  slice.width = 4, slice.height = 4, slice.channels = 3;
  slice.pixels.assign(4 * 4 * 3, 90);
  for (int n = 0; n < 3; ++n)
    writePng((slices / ("s" + std::to_string(n) + ".png")).string(), slice);
  const std::string before = readWholeFile(slices / "s1.png");
  CliRun r = ewaview(
      dir, slices.string() + " --resolution 16,16 --output " + (slices / "s1.png").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("is an input file"), std::string::npos) << r.err;
  // A turntable whose frames would land on the slices: refused before a frame is drawn.
  r = ewaview(dir, slices.string() + " --resolution 16,16 --turntable 3 --output " +
                       (slices / "s%d.png").string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(readWholeFile(slices / "s1.png"), before);
  // A MetaImage pair saved where its data file would be the input's: the input is kept, the new
  // pair takes another data name.
  const fs::path raw = dir / "scan.raw";
  std::ofstream(raw, std::ios::binary) << std::string(8, '\x40');
  std::ofstream(dir / "in.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
                                   "ElementType = MET_UCHAR\nElementDataFile = scan.raw\n";
  r = ewaview(dir, (dir / "in.mhd").string() + " --save-volume " + (dir / "scan.mhd").string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(readWholeFile(raw), std::string(8, '\x40'));
  EXPECT_TRUE(fs::exists(dir / "scan.1.raw"));
}

TEST(GlFaults, ScreenshotReplacesAFileWholeAndLeavesNoTemporaryFile) {
  const fs::path dir = scratch();
  const fs::path out = dir / "shot.png";
  std::ofstream(out) << "old contents";
  const CliRun r = ewaview(dir, "--synthetic sphere:8 --resolution 16,12 --output " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const Image8 img = readPng(out.string());
  EXPECT_EQ(img.width, 16);
  EXPECT_EQ(img.height, 12);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    files += entry.path().filename() != "stderr.txt";
  EXPECT_EQ(files, 1) << "a temporary file was left beside the screenshot";
  // An output folder that does not exist: one line, nothing created.
  const CliRun bad = ewaview(dir, "--synthetic sphere:8 --resolution 16,12 --output " +
                                      (dir / "no" / "such" / "x.png").string());
  EXPECT_EQ(bad.code, 1);
  EXPECT_EQ(lineCount(bad.err), 1) << bad.err;
}

}  // namespace
}  // namespace ewa::test
