// ewaview-mpi under mpirun against the one-process ewaview picture (early termination off): on
// 1 to 8 ranks, perspective and orthographic, oblique views, composite, X-ray and MIP, a
// synthetic and a shared volume, SSIM >= 0.999 and no channel off by more than 10 levels;
// turntables and tours frame by frame; formats rank 0 reads whole and scatters; a file missing
// on every rank or on one ends all ranks with one line, a rank killed mid-frame ends them all,
// and usage errors are one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.h"
#include "core/image_metrics.h"
#include "core/synthetic_volume.h"
#include "image_compare.h"
#include "io/camera_bookmarks.h"
#include "io/frame_names.h"
#include "io/png_io.h"
#include "io/volume_writer.h"
#include "python_fixtures.h"

namespace ewa::test {
namespace {

constexpr double kMinSsim = 0.999;
constexpr int kMaxLevels = 10;
constexpr int kTimeout = 120;  // seconds: a hung rank fails the test instead of hanging CTest

const std::string kSynthetic = "--synthetic marschner-lobb:41 --resolution 128,128";

std::string outPath(const std::string& name) {
  return testOutputDir() + "/mpi_" + name + ".png";
}

CliRun runRanks(int ranks, const std::string& args, const std::string& prefix) {
  return runProgram(EWA_MPIEXEC, std::to_string(ranks) + " " + EWA_MPI_BINARY + " " + args, prefix,
                    kTimeout);
}

FloatImage floatImage(const Image8& image) {
  FloatImage out(image.width, image.height, image.channels);
  for (size_t i = 0; i < image.pixels.size(); ++i) out.values[i] = float(image.pixels[i]);
  return out;
}

void expectNearPicture(const Image8& picture, const Image8& reference) {
  ASSERT_EQ(picture.width, reference.width);
  ASSERT_EQ(picture.height, reference.height);
  EXPECT_LE(maxDifference(picture, reference), kMaxLevels);
  EXPECT_GE(structuralSimilarity(floatImage(picture), floatImage(reference), 255.0), kMinSsim);
  EXPECT_GT(meanValue(picture), 1.0) << "an empty picture";
}

// The one-process frames of `args` (a --turntable or --tour of `frames` frames written to a
// folder), and each rank count's against them frame by frame; with `badFraction`, that share of
// the covered pixels may be off by more than kMaxLevels.
void expectSameFrames(const std::string& name, const std::string& args, int frames,
                      std::initializer_list<int> rankCounts, double badFraction = 0.0) {
  const std::string common = args + " --termination 1 --output ";
  const std::string one = testOutputDir() + "/mpi_" + name + "_one";
  std::filesystem::remove_all(one);
  const CliRun r = runEwaview(common + one, name);
  ASSERT_EQ(r.code, 0) << r.err;
  for (int ranks : rankCounts) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string folder = testOutputDir() + "/mpi_" + name + "_np" + std::to_string(ranks);
    std::filesystem::remove_all(folder);
    const CliRun run = runRanks(ranks, common + folder, name);
    ASSERT_EQ(run.code, 0) << run.err;
    for (int f = 0; f < frames; ++f) {
      SCOPED_TRACE("frame " + std::to_string(f));
      const Image8 picture = readPng(frameFileName(FrameNaming{false, folder}, f, frames));
      const Image8 reference = readPng(frameFileName(FrameNaming{false, one}, f, frames));
      if (badFraction == 0.0) {
        expectNearPicture(picture, reference);
        continue;
      }
      EXPECT_GE(structuralSimilarity(floatImage(picture), floatImage(reference), 255.0), kMinSsim);
      const ImageDifference d =
          compareCovered(picture, reference, backgroundRgb8(0, 0, 0), kMaxLevels);
      EXPECT_LE(d.badFraction, badFraction) << d.badFraction * d.covered << " pixels";
    }
    EXPECT_FALSE(std::filesystem::exists(frameFileName(FrameNaming{false, folder}, frames, frames)))
        << "more frames than asked for";
  }
}

// The one-process picture of `args`, and each rank count's against it.
void expectSamePicture(const std::string& name, const std::string& args,
                       std::initializer_list<int> rankCounts) {
  const std::string common = args + " --termination 1";
  const CliRun one = runEwaview(common + " --output " + outPath(name + "_one"), name);
  ASSERT_EQ(one.code, 0) << one.err;
  const Image8 reference = readPng(outPath(name + "_one"));
  for (int ranks : rankCounts) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string out = outPath(name + "_np" + std::to_string(ranks));
    const CliRun run = runRanks(ranks, common + " --output " + out, name);
    ASSERT_EQ(run.code, 0) << run.err;
    expectNearPicture(readPng(out), reference);
  }
}

TEST(MpiRender, OneToEightRanksDrawTheOneProcessPicture) {
  expectSamePicture("default", kSynthetic, {1, 2, 3, 4, 8});
}

TEST(MpiRender, ObliqueOrthographicAndPerspectiveViews) {
  // Pre-classified: every kernel's share is cut exactly at the brick faces, so the bricks add up
  // to the whole picture to the 8-bit noise floor from any side.
  const std::string oblique = kSynthetic + " --camera-position 75,-40,95 --classification pre";
  expectSamePicture("oblique", oblique, {3});
  expectSamePicture("orthographic", oblique + " --camera-orthographic", {3});
}

TEST(MpiRender, PostClassifiedSlabsAcrossBrickFacesStayNearTheWholePicture) {
  // Post-classified, a slab that a brick face crosses obliquely is classified on each side
  // apart (its mean value over part of its kernels), so pixels along the faces' edges on screen
  // may differ where the transfer function is steep: Marschner-Lobb's opaque boundary seen
  // close up, 3 ranks, leaves a few pixels off by up to about 50 levels.
  const std::string args = kSynthetic + " --camera-position 75,-40,95 --termination 1 --output ";
  ASSERT_EQ(runEwaview(args + outPath("post_one"), "post").code, 0);
  const CliRun run = runRanks(3, args + outPath("post_np3"), "post");
  ASSERT_EQ(run.code, 0) << run.err;
  const Image8 reference = readPng(outPath("post_one")), picture = readPng(outPath("post_np3"));
  EXPECT_GE(structuralSimilarity(floatImage(picture), floatImage(reference), 255.0), kMinSsim);
  const ImageDifference d = compareCovered(picture, reference, backgroundRgb8(0, 0, 0), kMaxLevels);
  EXPECT_LE(d.badFraction, 0.002) << d.badFraction * d.covered << " pixels";
  EXPECT_LE(d.mean, 0.2);
}

TEST(MpiRender, XRaySumsAndMipTakesTheMaximum) {
  expectSamePicture("xray", kSynthetic + " --render-mode xray --xray-scale 0.05", {3});
  expectSamePicture("mip", kSynthetic + " --render-mode mip --background 0.2,0.3,0.4", {2});
}

TEST(MpiRender, SharedVolumeWithAnOpaqueBackground) {
  const std::string file = std::string(EWA_SHARED_DATA) + "/neghip/neghip.slc";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " absent";
  expectSamePicture("neghip",
                    file +
                        " --resolution 160,160 --camera-position 150,-90,110 "
                        "--background 0.1,0.1,0.2",
                    {2, 3});
}

// Marschner-Lobb 41^3 as float32 voxels, written raw (x fastest, little-endian: this host).
std::string writeMarschnerLobbRaw() {
  const std::string file = testOutputDir() + "/mpi_ml41.raw";
  const Volume v = makeSyntheticVolume("marschner-lobb:41").volume;
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(v.bytes().data()), std::streamsize(v.bytes().size()));
  return file;
}

TEST(MpiRender, RawAndNrrdFilesReadByBricksDrawTheOneProcessPicture) {
  // Each rank reads its brick and ghosts by offsets; the value range and histogram behind the
  // default transfer function (no sidecar) are agreed on over the ranks.
  const std::string raw = writeMarschnerLobbRaw();
  const std::string view = " --resolution 128,128 --camera-position 75,-40,95";
  expectSamePicture("raw", raw + " --raw-dims 41,41,41 --raw-type float32" + view, {2});
  const std::string nrrd = testOutputDir() + "/mpi_ml41.nhdr";
  std::ofstream(nrrd) << "NRRD0004\ntype: float\ndimension: 3\nsizes: 41 41 41\n"
                         "spacings: 1 1 1.5\nendian: little\nencoding: raw\n"
                         "data file: mpi_ml41.raw\n";
  expectSamePicture("nrrd", nrrd + view, {3});
}

TEST(MpiRender, OmeZarrReadByChunksDrawsTheOneProcessPicture) {
  if (const std::string why = ewa::testing::pythonLacks("zarr, numcodecs, numpy"); !why.empty())
    GTEST_SKIP() << why;
  const std::string raw = writeMarschnerLobbRaw();
  const std::string folder = testOutputDir() + "/mpi_zarr";
  std::filesystem::create_directories(folder);
  const std::string script = R"PY(
import os, sys
import numpy as np
import zarr
from numcodecs import Blosc
out = sys.argv[1]
v = np.fromfile(os.path.join(out, '..', 'mpi_ml41.raw'), dtype='<f4').reshape(41, 41, 41)
g = zarr.open_group(os.path.join(out, 'ml.zarr'), mode='w')
g.create_dataset('0', data=v, chunks=(8, 16, 16), compressor=Blosc('zstd', 3, Blosc.SHUFFLE))
space = lambda n: {'name': n, 'type': 'space'}
g.attrs['multiscales'] = [{'version': '0.4', 'axes': [space('z'), space('y'), space('x')],
  'datasets': [{'path': '0', 'coordinateTransformations': [{'type': 'scale', 'scale': [1.5, 1, 1]}]}]}]
)PY";
  ASSERT_EQ(ewa::testing::runPython(script, folder), "");
  // Pre-classified: the oblique view's post-classified residual at brick faces (above) is not
  // what this test is about; the chunks read are.
  const std::string view = " --resolution 128,128 --camera-position 75,-40,95 --classification pre";
  expectSamePicture("zarr", folder + "/ml.zarr" + view, {2, 3});
}

TEST(MpiRender, Hdf5ReadByHyperslabsDrawsTheOneProcessPicture) {
  if (const std::string why = ewa::testing::pythonLacks("h5py, numpy"); !why.empty())
    GTEST_SKIP() << why;
  const std::string raw = writeMarschnerLobbRaw();
  const std::string folder = testOutputDir() + "/mpi_hdf5";
  std::filesystem::create_directories(folder);
  // As simulation codes write them: a chunked dataset inside a group, z slowest.
  const std::string script = R"PY(
import os, sys
import numpy as np
import h5py
out = sys.argv[1]
v = np.fromfile(os.path.join(out, '..', 'mpi_ml41.raw'), dtype='<f4').reshape(41, 41, 41)
with h5py.File(os.path.join(out, 'ml.h5'), 'w') as f:
    f.create_dataset('fields/density', data=v, chunks=(8, 16, 16))
)PY";
  ASSERT_EQ(ewa::testing::runPython(script, folder), "");
  const std::string view = " --resolution 128,128 --camera-position 75,-40,95 --classification pre";
  expectSamePicture("hdf5", folder + "/ml.h5 --dataset fields/density" + view, {3});
}

TEST(MpiRender, AFormatReadWholeSaysSoInOneLine) {
  const std::string file = std::string(EWA_SHARED_DATA) + "/neghip/neghip.slc";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " absent";
  const CliRun run =
      runRanks(2, file + " --resolution 32,32 --output " + outPath("whole"), "whole");
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string line =
      "ewaview-mpi: note: rank 0 reads the whole of neghip.slc (it is not read by parts) and "
      "sends each rank its brick";
  const size_t at = run.err.find(line);
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("reads the whole", at + line.size()), std::string::npos) << run.err;
}

TEST(MpiRender, ANiftiFileRank0ScattersDrawsTheOneProcessPicture) {
  // NIfTI is read only whole: rank 0 loads it and sends each rank its brick and ghosts, which
  // overlap; split by voxel count and by visible voxels.
  const std::string file = testOutputDir() + "/mpi_ml41.nii";
  writeVolume(file, makeSyntheticVolume("marschner-lobb:41").volume);
  const std::string view = " --resolution 128,128 --camera-position 75,-40,95 --classification pre";
  expectSamePicture("nifti", file + view, {3});
  expectSamePicture("nifti_voxels", file + view + " --split voxels", {2});
}

TEST(MpiRender, ATurntableDrawsEwaviewsFrames) {
  // Each frame is one collective render along ewaview's camera path; rank 0 writes them.
  expectSameFrames("turntable", kSynthetic + " --turntable 3", 3, {2, 3});
}

TEST(MpiRender, ATourDrawsEwaviewsFrames) {
  // Every rank reads the bookmarks; the stops' crop boxes cut the bricks too.
  const std::string dir = testOutputDir() + "/mpi_tour_marks";
  std::filesystem::create_directories(dir);
  auto at = [](glm::dvec3 position) {
    Camera c;
    c.position = position;
    c.focalPoint = {20.0, 20.0, 20.0};
    c.viewUp = {0.0, 0.0, 1.0};
    return c;
  };
  std::vector<CameraBookmark> marks(2);
  marks[0] = {"front", at({20.0, -80.0, 40.0}), {}};
  marks[1] = {"side", at({100.0, 30.0, 50.0}), {}};
  marks[1].clip.cropEnabled = true;
  marks[1].clip.cropMin = {0, 0, 0};
  marks[1].clip.cropMax = {40, 40, 22};
  const std::string bookmarks = dir + "/ml.bookmarks.json";
  saveBookmarks(bookmarks, marks);
  // Between the stops the crop box moves: where its face and a brick face cut the same kernels
  // the two cuts' shares are approximated (measured: 3 pixels of the middle frame off by 11 to
  // 13 levels, the stops within 1).
  expectSameFrames("tour", kSynthetic + " --classification pre --tour 3 --bookmarks " + bookmarks,
                   3, {2}, 0.002);
}

TEST(MpiRender, AnUnwritableTurntableEndsAllRanksWithOneLine) {
  // Rank 0 alone opens the sink; the others learn of its failure and stop with it.
  const std::string file = testOutputDir() + "/mpi_not_a_folder";
  std::ofstream(file) << "a file";
  const CliRun run =
      runRanks(2, kSynthetic + " --turntable 3 --output " + file + "/frames/", "unwritable");
  EXPECT_EQ(run.code, 1);
  const size_t at = run.err.find("ewaview-mpi: rank 0 of 2: ");
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_NE(run.err.find("mpi_not_a_folder", at), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("ewaview-mpi:", at + 1), std::string::npos) << "said twice: " << run.err;
}

TEST(MpiRender, AFileMissingOnEveryRankEndsAllWithOneLine) {
  const CliRun run =
      runRanks(2, "/nonexistent/volume.nrrd --output " + outPath("missing"), "missing");
  EXPECT_EQ(run.code, 1);
  const size_t at = run.err.find("ewaview-mpi: rank 0 of 2: ");
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("ewaview-mpi:", at + 1), std::string::npos) << "said twice: " << run.err;
  EXPECT_NE(run.err.find("/nonexistent/volume.nrrd"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(outPath("missing")));
}

TEST(MpiRender, AFileMissingOnOneRankEndsAllWithItsLine) {
  // Rank 0 reads a volume, rank 1 (a second program of the same run) a file it does not have.
  const std::string out = " --resolution 32,32 --output " + outPath("missing_one");
  const CliRun run =
      runProgram(EWA_MPIEXEC,
                 std::string("1 ") + EWA_MPI_BINARY + " " + kSynthetic + out + " : " +
                     EWA_MPI_NP_FLAG + " 1 " + EWA_MPI_BINARY + " /nonexistent/brick.nrrd" + out,
                 "missing_one", kTimeout);
  EXPECT_EQ(run.code, 1);
  const size_t at = run.err.find("ewaview-mpi: rank 1 of 2: ");
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("ewaview-mpi:", at + 1), std::string::npos) << "said twice: " << run.err;
  EXPECT_EQ(run.err.find("ewaview-mpi: rank 0"), std::string::npos) << run.err;
}

TEST(MpiRender, ARankKilledMidFrameEndsEveryRank) {
  // Rank 1 is killed a second into a frame that takes longer: mpirun ends rank 0 too (no hang
  // in a collective), exits non-zero, says which process, and no picture is written.
  const std::string args =
      "--synthetic marschner-lobb:96 --resolution 1024,1024 --output " + outPath("killed");
  const std::string victim = std::string("/bin/sh -c '") + EWA_MPI_BINARY + " " + args +
                             " & sleep 1; kill -9 $!; wait $!'";
  const CliRun run = runProgram(
      EWA_MPIEXEC,
      std::string("1 ") + EWA_MPI_BINARY + " " + args + " : " + EWA_MPI_NP_FLAG + " 1 " + victim,
      "killed", kTimeout);
  EXPECT_NE(run.code, 0);
  EXPECT_NE(run.code, 124) << "timed out: a rank hung";
  EXPECT_NE(run.err.find("Exit code:    137"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(outPath("killed")));
}

TEST(MpiRender, UsageErrorsAreOneLine) {
  // Without --output the window opens; --info is for ewaview.
  const CliRun info = runRanks(2, kSynthetic + " --info", "usage");
  EXPECT_EQ(info.code, 2);
  EXPECT_NE(info.err.find("ewaview-mpi: --info, --pick and --save-volume need no ranks"),
            std::string::npos)
      << info.err;
  const CliRun badOption = runRanks(2, "--no-such-option", "usage");
  EXPECT_EQ(badOption.code, 2);
  // The parser's message from rank 0 only (mpirun adds its own report of the exit status).
  const size_t said = badOption.err.find("no-such-option");
  ASSERT_NE(said, std::string::npos) << badOption.err;
  EXPECT_EQ(badOption.err.find("no-such-option", said + 1), std::string::npos) << badOption.err;
  // --level of a volume that is not an OME-Zarr image: one line naming it.
  const std::string raw = writeMarschnerLobbRaw();
  const CliRun level = runRanks(
      2, raw + " --raw-dims 41,41,41 --raw-type float32 --level 1 --output " + outPath("level"),
      "usage");
  EXPECT_EQ(level.code, 2);
  const size_t named = level.err.find(raw + ": --level 1 picks a level of an OME-Zarr pyramid");
  ASSERT_NE(named, std::string::npos) << level.err;
  EXPECT_EQ(level.err.find("--level 1", named + raw.size() + 12), std::string::npos) << level.err;
}

// The window's frames without a window (EWAVIEW_MPI_SCRIPT): rank 0 sends three frame
// descriptions the window's way (DistributedRenderer: a camera change, a new transfer function,
// a crop box), every rank draws its brick, and each composite is ewaview's picture of the same
// options. Then the quit description ends both ranks with status 0.
TEST(MpiRender, WindowFramesDrawTheOneProcessPictures) {
  const std::string base = kSynthetic + " --termination 1 --classification pre";
  const std::string tf = std::string(EWA_TEST_DIR) + "/window/ml_test.tf.json";
  const std::vector<std::pair<std::string, std::string>> frames = {
      {"camera", " --camera-position 75,-40,95"},
      {"tf", " --camera-position 75,-40,95 --tf " + tf},
      {"crop", " --camera-position 75,-40,95 --tf " + tf + " --crop 5,35,-1,30,8,40"},
  };
  const std::string script = testOutputDir() + "/mpi_window_script.txt";
  {
    std::ofstream lines(script);
    for (const auto& [name, options] : frames)
      lines << outPath("window_" + name) << options << "\n";
  }
  const CliRun run =
      runProgram("env EWAVIEW_MPI_SCRIPT=" + script + " " + EWA_MPIEXEC,
                 "2 " + std::string(EWA_MPI_BINARY) + " " + base, "window", kTimeout);
  ASSERT_EQ(run.code, 0) << run.err;
  for (const auto& [name, options] : frames) {
    SCOPED_TRACE(name);
    const std::string one = outPath("window_" + name + "_one");
    ASSERT_EQ(runEwaview(base + options + " --output " + one, "window").code, 0);
    const Image8 reference = readPng(one), picture = readPng(outPath("window_" + name));
    ASSERT_EQ(picture.width, reference.width);
    ASSERT_EQ(picture.height, reference.height);
    EXPECT_LE(maxDifference(picture, reference), kMaxLevels);
    EXPECT_GE(structuralSimilarity(floatImage(picture), floatImage(reference), 255.0), kMinSsim);
    EXPECT_GT(meanValue(picture), 1.0) << "an empty picture";
  }
}

// Without a display the window cannot open: rank 0 says so in one line and the quit
// description ends the other rank too, with the same status, instead of leaving it waiting.
TEST(MpiRender, AWindowThatCannotOpenEndsEveryRank) {
  const CliRun run =
      runProgram("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(EWA_MPIEXEC),
                 "2 " + std::string(EWA_MPI_BINARY) + " " + kSynthetic, "nowindow", kTimeout);
  EXPECT_EQ(run.code, 1) << run.err;
  EXPECT_NE(run.err.find("ewaview: "), std::string::npos) << run.err;
}

}  // namespace
}  // namespace ewa::test
