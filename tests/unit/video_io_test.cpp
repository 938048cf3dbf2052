// VideoWriter, readVideo and the turntable frame sinks: frames, sizes, colours, temporaries.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "io/atomic_file.h"
#include "io/frame_sink.h"
#include "io/png_io.h"
#include "io/video_reader.h"
#include "io/video_writer.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ewa_video_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Image8 flat(int w, int h, int r, int g, int b, int channels = 3) {
  Image8 img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  img.pixels.resize(size_t(w) * h * channels, 255);
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    img.pixels[p * channels] = uint8_t(r);
    img.pixels[p * channels + 1] = uint8_t(g);
    img.pixels[p * channels + 2] = uint8_t(b);
  }
  return img;
}

// A flat colour survives RGB -> YUV 4:2:0 -> codec -> RGB within one level per channel in
// both codecs (exact conversions, full-chroma interpolation on the way back), whatever order
// the frames change colour in, and RGBA frames are taken as RGB.
TEST(VideoIo, FlatColoursRoundTripWithinOneLevel) {
  const fs::path dir = freshDir("flat");
  const int colours[4][3] = {{128, 128, 128}, {200, 100, 50}, {10, 240, 30}, {250, 250, 250}};
  for (const char* name : {"flat.mp4", "flat.webm"}) {
    const std::string path = (dir / name).string();
    {
      VideoWriter writer(path, 25);
      for (int f = 0; f < 4; ++f)
        writer.add(flat(64, 48, colours[f][0], colours[f][1], colours[f][2], f % 2 ? 4 : 3));
      writer.finish();
      EXPECT_EQ(writer.width(), 64);
      EXPECT_EQ(writer.height(), 48);
    }
    const DecodedVideo video = readVideo(path);
    EXPECT_DOUBLE_EQ(video.fps, 25.0) << name;
    ASSERT_EQ(video.frames.size(), 4u) << name;
    for (int f = 0; f < 4; ++f) {
      const Image8& img = video.frames[size_t(f)];
      ASSERT_EQ(img.channels, 3);
      const size_t centre = (size_t(24) * 64 + 32) * 3;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(img.pixels[centre + c], colours[f][c], 1)
            << name << " frame " << f << " c" << c;
    }
  }
}

TEST(VideoIo, LaterFramesOfAnotherSizeAreScaledToTheFirst) {
  const fs::path dir = freshDir("sizes");
  const std::string path = (dir / "sizes.mp4").string();
  VideoWriter writer(path, 30);
  writer.add(flat(33, 21, 90, 90, 90));  // odd: 32x20
  writer.add(flat(64, 40, 90, 90, 90));
  writer.finish();
  const DecodedVideo video = readVideo(path);
  ASSERT_EQ(video.frames.size(), 2u);
  for (const Image8& img : video.frames) {
    EXPECT_EQ(img.width, 32);
    EXPECT_EQ(img.height, 20);
    EXPECT_NEAR(img.pixels[(10 * 32 + 16) * 3], 90, 1);
  }
}

TEST(VideoIo, UnfinishedVideosLeaveNoFiles) {
  const fs::path dir = freshDir("unfinished");
  {
    VideoWriter writer((dir / "a.webm").string(), 30);
    writer.add(flat(16, 16, 1, 2, 3));
  }  // destroyed without finish(): the temporary goes
  {
    VideoWriter writer((dir / "b.mp4").string(), 30);
    EXPECT_THROW(writer.finish(), std::runtime_error);  // no frames
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(VideoIo, BadArgumentsAndFilesAreOneLineErrors) {
  const fs::path dir = freshDir("bad");
  EXPECT_THROW(VideoWriter((dir / "x.mp4").string(), 0), std::runtime_error);
  EXPECT_THROW(VideoWriter((dir / "x.avi").string(), 30), std::runtime_error);
  VideoWriter tiny((dir / "t.mp4").string(), 30);
  EXPECT_THROW(tiny.add(flat(1, 1, 0, 0, 0)), std::runtime_error);
  writeFileAtomically((dir / "junk.mp4").string(), "not a video");
  try {
    readVideo((dir / "junk.mp4").string());
    FAIL() << "junk decoded";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind((dir / "junk.mp4").string() + ": ", 0), 0u) << e.what();
  }
}

TEST(FrameSink, PicksPngFramesOrAVideoByName) {
  EXPECT_TRUE(isVideoPath("a/spin.MP4"));
  EXPECT_TRUE(isVideoPath("spin.webm"));
  EXPECT_FALSE(isVideoPath("frames"));
  EXPECT_FALSE(isVideoPath("f_%03d.png"));
  const fs::path dir = freshDir("sink");
  const auto pngs = openFrameSink((dir / "frames").string(), 12, 30);
  EXPECT_TRUE(fs::is_directory(dir / "frames"));  // made before any frame
  EXPECT_EQ(pngs->fileOf(11), (dir / "frames" / "frame_011.png").string());
  const auto video = openFrameSink((dir / "spin.webm").string(), 12, 30);
  EXPECT_EQ(video->fileOf(3), (dir / "spin.webm").string());
  EXPECT_THROW(openFrameSink((dir / "spin.gif").string(), 12, 30), std::runtime_error);
  EXPECT_THROW(openFrameSink((dir / "x").string(), 0, 30), std::invalid_argument);
}

// PNG frames are encoded on worker threads: after finish() every frame is its file, each the
// picture given; a frame that cannot be written fails a later add() or finish(), naming it.
TEST(FrameSink, PngFramesAreWrittenOnWorkersAndTheirFailuresReported) {
  const fs::path dir = freshDir("sink_pngs");
  const int count = 20;
  {
    const auto sink = openFrameSink((dir / "frames").string(), count, 30);
    for (int f = 0; f < count; ++f) sink->add(flat(33, 17, f * 10, 255 - f * 10, 7), f);
    sink->finish();
    for (int f = 0; f < count; ++f) {
      const Image8 png = readPng(sink->fileOf(f));
      ASSERT_EQ(png.width, 33) << f;
      ASSERT_EQ(png.height, 17) << f;
      EXPECT_EQ(int(png.pixels[0]), f * 10) << f;
      EXPECT_EQ(int(png.pixels[1]), 255 - f * 10) << f;
      EXPECT_EQ(int(png.pixels[2]), 7) << f;
    }
  }
  // Frame 5's name taken by a folder: its file cannot be renamed into place.
  auto sink = openFrameSink((dir / "broken").string(), count, 30);
  const std::string before = sink->fileOf(4);
  fs::create_directories(sink->fileOf(5));
  try {
    for (int f = 0; f < count; ++f) sink->add(flat(8, 8, 0, 0, 0), f);
    sink->finish();
    FAIL() << "the frame that could not be written was not reported";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(sink->fileOf(5) + ": ", 0), 0u) << e.what();
  }
  sink.reset();  // the frames handed over are written before it is gone
  EXPECT_TRUE(fs::exists(before));
}

}  // namespace
}  // namespace ewa
