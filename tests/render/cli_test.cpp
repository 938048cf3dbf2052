// The ewaview program as a user runs it: exit codes, messages, --info, headless PNG output.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "app/scene.h"
#include "ci_skip.h"
#include "cli_run.h"
#include "image_compare.h"
#include "io/png_io.h"

namespace ewa::test {
namespace {

CliRun ewaview(const std::string& args) {
  return runEwaview(args, "cli");
}

TEST(Cli, VersionAndHelpExitZero) {
  CliRun r = ewaview("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("ewaview 0."), std::string::npos) << r.out;
  r = ewaview("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* opt :
       {"--output", "--resolution", "--camera-position", "--camera-focal-point", "--camera-view-up",
        "--camera-view-angle", "--camera-orthographic", "--filter", "--cutoff", "--slab-thickness",
        "--tf", "--background", "--backend", "--info", "--synthetic", "--raw-dims"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt << " missing from --help";
}

// The launcher (ewaview) starts the viewer beside it (libexec/ewaview) through a link from
// elsewhere too, and without the viewer says so in one line.
TEST(Cli, TheLauncherStartsTheViewerBesideItOrSaysWhyNot) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(testOutputDir()) / "launcher";
  fs::remove_all(dir);
  fs::create_directories(dir / "linked");
  fs::create_symlink(fs::absolute(EWA_BINARY), dir / "linked" / "ewaview");
  const CliRun linked = runProgram((dir / "linked" / "ewaview").string(), "--version", "linked");
  ASSERT_EQ(linked.code, 0) << linked.err;
  EXPECT_NE(linked.out.find("ewaview"), std::string::npos) << linked.out;
  // A copy without the viewer beside it.
  fs::create_directories(dir / "alone");
  fs::copy_file(fs::absolute(EWA_BINARY), dir / "alone" / "ewaview");
  const CliRun alone = runProgram((dir / "alone" / "ewaview").string(), "--version", "alone");
  EXPECT_EQ(alone.code, 127);
  EXPECT_TRUE(alone.out.empty()) << alone.out;
  EXPECT_NE(alone.err.find("cannot start the viewer " + (dir / "alone").string() +
                           "/libexec/ewaview: No such file"),
            std::string::npos)
      << alone.err;
  EXPECT_EQ(std::count(alone.err.begin(), alone.err.end(), '\n'), 1) << alone.err;
}

// The options page lists what exists: every option --help prints is in it, written as `--name`
// (docs/user/options.md is generated from the option table; the unit tests compare it).
TEST(Cli, EveryOptionOfHelpIsInTheOptionsPage) {
  const CliRun r = ewaview("--help");
  ASSERT_EQ(r.code, 0);
  std::ifstream in(std::string(EWA_TEST_DIR) + "/../docs/user/options.md");
  ASSERT_TRUE(in) << "docs/user/options.md not found beside tests/";
  const std::string readme((std::istreambuf_iterator<char>(in)), {});
  std::istringstream lines(r.out);
  int options = 0;
  for (std::string line; std::getline(lines, line);) {
    // CLI11 prints an option as "  --name TYPE  description" (or "  -o,--name ...").
    const size_t dashes = line.find("--");
    if (line.rfind("  ", 0) != 0 || dashes == std::string::npos ||
        line.find_first_not_of(" -ho,") < dashes)
      continue;
    const size_t end = line.find_first_of(" =", dashes);
    const std::string name = line.substr(dashes, end - dashes);
    if (name == "--help") continue;
    ++options;
    EXPECT_NE(readme.find("`" + name), std::string::npos) << name << " is not in the options page";
  }
  EXPECT_GT(options, 40) << r.out;
}

TEST(Cli, EachChannelTakesItsOwnSidecarTransferFunction) {
  EXPECT_EQ(sidecarTransferFunctionPath("/d/cells.ome.tif"), "/d/cells.ome.tf.json");
  EXPECT_EQ(sidecarTransferFunctionPath("/d/cells.nrrd", 2), "/d/cells.c2.tf.json");
  // Two channels (a ball of 200, one of 40): channel 0 red by cells.tf.json, channel 1 green
  // by cells.c1.tf.json; each opaque over its own value only.
  const std::string dir = testOutputDir() + "/sidecars";
  std::filesystem::create_directories(dir);
  std::string data;
  const int n = 16;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double r2 = (x - 7.5) * (x - 7.5) + (y - 7.5) * (y - 7.5) + (z - 7.5) * (z - 7.5);
        data += char(r2 < 36 ? 200 : 0);
        data += char(r2 < 36 ? 40 : 0);
      }
  std::ofstream(dir + "/cells.nrrd", std::ios::binary)
      << "NRRD0004\ntype: uint8\ndimension: 4\nsizes: 2 16 16 16\n"
         "kinds: 2-vector domain domain domain\nencoding: raw\n\n"
      << data;
  std::ofstream(dir + "/cells.tf.json")
      << R"({"opacity": [[0, 0], [150, 0], [200, 1], [255, 1]], "color": [[0, 1, 0, 0], [255, 1, 0, 0]]})";
  std::ofstream(dir + "/cells.c1.tf.json")
      << R"({"opacity": [[0, 0], [20, 0], [40, 1], [255, 1]], "color": [[0, 0, 1, 0], [255, 0, 1, 0]]})";
  for (int channel : {0, 1}) {
    const std::string png = dir + "/channel" + std::to_string(channel) + ".png";
    const CliRun r = ewaview(dir + "/cells.nrrd --channel " + std::to_string(channel) +
                             " --resolution 64,64 -o " + png);
    ASSERT_EQ(r.code, 0) << r.err;
    const Image8 image = readPng(png);
    const uint8_t* centre = &image.pixels[size_t((32 * 64 + 32) * image.channels)];
    EXPECT_GT(centre[channel == 0 ? 0 : 1], 150) << "channel " << channel;
    EXPECT_LT(centre[channel == 0 ? 1 : 0], 30) << "channel " << channel;
  }
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(ewaview("--no-such-option").code, 2);
  EXPECT_EQ(ewaview("--synthetic sphere --filter blurry").code, 2);
  EXPECT_EQ(ewaview("--synthetic sphere --resolution 10").code, 2);
  // Given twice the last counts, but each must be whole: not the last two of three numbers.
  EXPECT_EQ(ewaview("--synthetic sphere --resolution 10,10,5 -o x.png").code, 2);
  EXPECT_EQ(ewaview("--synthetic sphere --resolution 8,8 --resolution=10,10,5 -o x.png").code, 2);
  EXPECT_EQ(ewaview("--synthetic sphere --camera-position=1,2,3,4 -o x.png").code, 2);
  const CliRun r = ewaview("--synthetic sphere --cutoff -1");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
}

TEST(Cli, BadInputIsOneLineNamingTheFileAndExitOne) {
  const std::string dir = testOutputDir();
  const std::string missing = dir + "/no-such-volume.nrrd";
  CliRun r = ewaview(missing + " --info");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  const std::string badTf = dir + "/bad.tf.json";
  std::ofstream(badTf) << "{\"opacity\": [[0, 2.5]]}";
  r = ewaview("--synthetic sphere:8 --tf " + badTf + " --output " + dir + "/x.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(badTf), std::string::npos) << r.err;
  r = ewaview("--synthetic sphere:8 --output /no/such/dir/x.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("/no/such/dir/x.png"), std::string::npos) << r.err;
}

TEST(Cli, InfoPrintsOneJsonObject) {
  CliRun r = ewaview("--synthetic checkerboard --info");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(
      r.out,
      "{\"dims\":[400,400,1],\"spacing\":[1.0,1.0,1.0],\"type\":\"uint8\",\"range\":[1.0,2.0],"
      "\"origin\":[0.0,0.0,0.0],\"direction\":[[1.0,0.0,0.0],[0.0,1.0,0.0],[0.0,0.0,1.0]],"
      "\"space\":\"none\",\"unit\":null,\"frame\":0,\"frames\":1,\"channel\":0,\"channels\":1,"
      "\"series\":[],\"notes\":[]}\n");
  const std::string tooth = std::string(EWA_SHARED_DATA) + "/tooth/tooth.nrrd";
  if (!std::filesystem::exists(tooth)) GTEST_SKIP() << "shared data absent: " << tooth;
  r = ewaview(tooth + " --info");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"dims\":[103,94,161]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"type\":\"uint8\""), std::string::npos) << r.out;
  // Patient data: the direction and frame; --frame picks a time point, out of range is exit 1.
  const std::string nifti = std::string(EWA_SHARED_DATA) + "/nifti/functional.nii";
  r = ewaview(nifti + " --info --frame 19");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"space\":\"LPS\",\"unit\":\"mm\",\"frame\":19,\"frames\":20"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("20 frames; showing frame 19"), std::string::npos) << r.out;
  r = ewaview(nifti + " --info --frame 20");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("functional.nii: --frame 20 is out of range"), std::string::npos) << r.err;
  r = ewaview(std::string(EWA_SHARED_DATA) + "/dicom-pet/ --info --series 9.9");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("dicom-pet: no series '9.9' here (series: 1.3.6.1.4.1.14519"),
            std::string::npos)
      << r.err;
}

// A folder of image slices opens as a volume; --spacing replaces the spacing they lack.
TEST(Cli, SpacingReplacesTheFilesForAFolderOfImageSlices) {
  const std::string dir = testOutputDir() + "/slices";
  std::filesystem::create_directories(dir);
  for (int z = 0; z < 3; ++z)
    std::ofstream(dir + "/s" + std::to_string(z) + ".pgm", std::ios::binary)
        << "P5 4 2 255\n"
        << std::string(8, char(10 * z));
  CliRun r = ewaview(dir + " --info");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"dims\":[4,2,3],\"spacing\":[1.0,1.0,1.0]"), std::string::npos) << r.out;
  r = ewaview(dir + "/s1.pgm --info --spacing 0.5,0.25,2");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"spacing\":[0.5,0.25,2.0]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spacing 0.5, 0.25, 2 from --spacing (the file's: 1, 1, 1)"),
            std::string::npos)
      << r.out;
  // --save-volume writes it as NRRD, which reads back with that spacing and the same voxels.
  r = ewaview(dir + " --spacing 0.5,0.25,2 --save-volume " + dir + "/../slices.nrrd");
  EXPECT_EQ(r.code, 0) << r.err;
  r = ewaview(dir + "/../slices.nrrd --info");
  EXPECT_NE(r.out.find("\"dims\":[4,2,3],\"spacing\":[0.5,0.25,2.0],\"type\":\"uint8\",\"range\":"
                       "[0.0,20.0]"),
            std::string::npos)
      << r.out;
  r = ewaview(dir + " --save-volume " + dir + "/v.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("the file must end in .nrrd, .nii, .nii.gz, .mha, .mhd, .tif or .tiff"),
            std::string::npos)
      << r.err;
  r = ewaview(dir + " --info --spacing 1,-1,1");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--spacing 1,-1,1: each must be a positive number"), std::string::npos)
      << r.err;
}

// --save-volume with --crop writes only the voxels whose centres lie in the box, where they were.
TEST(Cli, SaveVolumeWithACropBoxWritesItsVoxels) {
  const std::string dir = testOutputDir() + "/save_crop";
  std::filesystem::create_directories(dir);
  // sphere:32 has its voxels at 0..31 on every axis; the box keeps x 4..10, y 0..31, z 20..31.
  CliRun r = ewaview("--synthetic sphere:32 --crop 3.5,10.2,-9,99,20,40 --save-volume " + dir +
                     "/part.nrrd --info");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"dims\":[7,32,12],\"spacing\":[1.0,1.0,1.0]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"origin\":[4.0,0.0,20.0]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cropped to voxels 4-10, 0-31, 20-31 of 32 x 32 x 32"), std::string::npos)
      << r.out;
  // As NIfTI (through the sform; read back with patient axes), MetaImage and OME-TIFF (each
  // slice's Plane position) the same box keeps its place.
  for (const char* name : {"part.nii.gz", "part.mha", "part.tif"}) {
    r = ewaview("--synthetic sphere:32 --crop 3.5,10.2,-9,99,20,40 --save-volume " + dir + "/" +
                name);
    ASSERT_EQ(r.code, 0) << r.err;
    r = ewaview(dir + "/" + name + " --info");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("\"dims\":[7,32,12],\"spacing\":[1.0,1.0,1.0]"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\"origin\":[4.0,0.0,20.0]"), std::string::npos) << r.out;
  }
  // What TIFF cannot keep, NIfTI's patient axes, gets a one-line note; the voxels are written.
  r = ewaview(dir + "/part.nii.gz --save-volume " + dir + "/patient.tif");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("ewaview: note: " + dir +
                       "/patient.tif: TIFF keeps no patient axes: the slices are written as "
                       "stored"),
            std::string::npos)
      << r.err;
  r = ewaview(dir + "/patient.tif --info");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"dims\":[7,32,12],\"spacing\":[1.0,1.0,1.0]"), std::string::npos) << r.out;
  r = ewaview("--synthetic sphere:32 --crop 40,50,0,9,0,9 --save-volume " + dir + "/none.nrrd");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("sphere:32: the crop box keeps no voxel of the volume (its centres lie in "
                       "0,31,0,31,0,31)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/none.nrrd"));
  r = ewaview("--synthetic sphere:32 --clip-plane 1,1,1,0,0,1 --save-volume " + dir + "/p.nrrd");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("a clipping plane cannot cut a grid"), std::string::npos) << r.err;
}

// --info's series list: each series' id, label and whether it is the one open, in order.
TEST(Cli, InfoListsTheSeriesOfAFolder) {
  Volume v({2, 2, 2}, glm::dvec3(1.0), glm::dvec3(0.0), ScalarType::UInt8,
           std::vector<uint8_t>(8, 0));
  v.setSeriesChoices(
      {{"1.2.3", "30 slices, AX", true}, {"1.2.3#2", "1 slices (part of 1.2.3: 5 x 6)", false}});
  const std::string json = volumeInfoJson(v);
  EXPECT_NE(json.find("\"series\":[{\"id\":\"1.2.3\",\"label\":\"30 slices, AX\",\"open\":true},"
                      "{\"id\":\"1.2.3#2\",\"label\":\"1 slices (part of 1.2.3: 5 x 6)\","
                      "\"open\":false}],\"notes\""),
            std::string::npos)
      << json;
}

TEST(Cli, HeadlessOutputOnBothBackendsAndTheDefaultAsset) {
  const std::string dir = testOutputDir();
  const std::string a = dir + "/cli_osmesa.png", b = dir + "/cli_egl.png";
  CliRun r = ewaview("--synthetic sphere:16 --resolution 64,48 --backend osmesa --output " + a);
  ASSERT_EQ(r.code, 0) << r.err;
  const Image8 ia = readPng(a);
  EXPECT_EQ(ia.width, 64);
  EXPECT_EQ(ia.height, 48);
  r = ewaview("--synthetic sphere:16 --resolution 64,48 --backend egl --output " + b);
  if (r.code != 0 && r.err.find("EGL") != std::string::npos) {
    EWA_SKIP_UNLESS_CI() << r.err;
  }
  ASSERT_EQ(r.code, 0) << r.err;
  const Image8 ib = readPng(b);
  ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
  int worst = 0;
  for (size_t p = 0; p < ia.pixels.size(); ++p)
    worst = std::max(worst, std::abs(ia.pixels[p] - ib.pixels[p]));
  EXPECT_LE(worst, 1) << "OSMesa and EGL pictures differ";
  // No FILE: the default volume in assets/.
  r = ewaview("--resolution 32,32 --output " + dir + "/cli_default.png");
  EXPECT_EQ(r.code, 0) << r.err;
}

// `-o /dev/stdout` (here redirected to a file, as cli_run does) writes the PNG into the file
// it is open on, and `-o /dev/null` into the device: neither name is replaced by a renamed
// file (run as root, both once were).
TEST(Cli, OutputIntoStdoutAndDevNullLeavesThemAsTheyWere) {
  struct stat before {};
  const bool hadLink = ::lstat("/dev/stdout", &before) == 0 && S_ISLNK(before.st_mode);
  CliRun r = ewaview("--synthetic sphere:16 --resolution 24,16 -o /dev/stdout");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string file = testOutputDir() + "/cli_stdout.png";
  std::ofstream(file, std::ios::binary) << r.out;
  const Image8 image = readPng(file);
  EXPECT_EQ(image.width, 24);
  EXPECT_EQ(image.height, 16);
  struct stat after {};
  if (hadLink) {
    ASSERT_EQ(::lstat("/dev/stdout", &after), 0);
    EXPECT_TRUE(S_ISLNK(after.st_mode)) << "/dev/stdout replaced";
  }
  r = ewaview("--synthetic sphere:16 --resolution 24,16 -o /dev/null");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/null replaced";
}

// EWAVIEW_BACKEND names the backend when --backend does not (a GPU server's egl, say).
TEST(Cli, EnvironmentNamesTheBackendWhenTheCommandLineDoesNot) {
  const std::string png = testOutputDir() + "/cli_env_backend.png";
  const std::string args = "--synthetic sphere:8 --resolution 16,16 --output " + png;
  std::filesystem::remove(png);
  CliRun r = runProgram("env EWAVIEW_BACKEND=vulkan " EWA_BINARY, args, "env_bad");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("EWAVIEW_BACKEND=\"vulkan\""), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(png));
  // The command line wins; a valid value in any case is taken.
  r = runProgram("env EWAVIEW_BACKEND=vulkan " EWA_BINARY, args + " --backend osmesa", "env_cli");
  EXPECT_EQ(r.code, 0) << r.err;
  r = runProgram("env EWAVIEW_BACKEND=OSMesa " EWA_BINARY, args, "env_good");
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace ewa::test

namespace ewa::test {
namespace {

TEST(Cli, RenderModeAndShadingOptions) {
  const std::string png = testOutputDir() + "/cli_modes.png";
  for (const char* args :
       {"--render-mode mip", "--render-mode xray --xray-map sum",
        "--shading --surface-threshold 200 --compositing back-to-front", "--depth-cutoff inf",
        "--depth-cutoff 2.25", "--classification post --shading --post-normals voxel"}) {
    std::filesystem::remove(png);
    const CliRun r = ewaview(std::string("--synthetic sphere:16 --resolution 24,24 ") + args +
                             " --output " + png);
    EXPECT_EQ(r.code, 0) << args << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(png)) << args;
  }
  for (const char* bad :
       {"--render-mode maximum", "--surface-threshold nan", "--termination 2",
        "--surface-threshold 1 --surface-opacity-threshold 0.5", "--surface-min-gradient 0.1",
        "--xray-map log", "--depth-cutoff 0", "--depth-cutoff nan", "--post-normals bent",
        "--cutoff nan", "--kernel-width=nan", "--camera-position 1,nan,2"}) {
    const CliRun r = ewaview(std::string("--synthetic sphere:16 -o x.png ") + bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(lineCount(r.err), 1) << bad << ": " << r.err;
  }
}

}  // namespace
}  // namespace ewa::test
