// writeFileAtomically and the writers built on it: whole files or nothing, no temporary files
// left, no links followed, inputs never replaced.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/transfer_function.h"
#include "io/png_io.h"
#include "io/transfer_function_io.h"

namespace ewa {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ewa_atomic_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

size_t entries(const fs::path& dir) {
  return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, WritesAndReplacesWholeFilesWithoutLeftovers) {
  const fs::path dir = freshDir("replace");
  const fs::path file = dir / "a.txt";
  writeFileAtomically(file.string(), "first");
  EXPECT_EQ(slurp(file), "first");
  writeFileAtomically(file.string(), std::string(100000, 'x'));
  EXPECT_EQ(slurp(file), std::string(100000, 'x'));
  writeFileAtomically(file.string(), "");
  EXPECT_EQ(slurp(file), "");
  EXPECT_EQ(entries(dir), 1u);
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  const mode_t mask = ::umask(022);
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
  fs::remove_all(dir);
}

TEST(AtomicFile, FailuresLeaveTheOldFileAndNoTemporaryFile) {
  const fs::path dir = freshDir("fail");
  EXPECT_THROW(writeFileAtomically((dir / "missing" / "a.txt").string(), "x"), std::runtime_error);
  fs::create_directories(dir / "sub");
  try {
    writeFileAtomically((dir / "sub").string(), "x");
    ADD_FAILURE() << "wrote over a directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(dir / "sub"));
  EXPECT_EQ(entries(dir), 1u);
  fs::remove_all(dir);
}

TEST(AtomicFile, ALinkAtTheTargetIsReplacedNotFollowed) {
  const fs::path dir = freshDir("link");
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "keep me";
  fs::create_symlink(victim, dir / "out.txt");
  // A link planted where the old fixed temporary name "out.txt.tmp" was is ignored too.
  fs::create_symlink(victim, dir / "out.txt.tmp");
  writeFileAtomically((dir / "out.txt").string(), "new");
  EXPECT_EQ(slurp(victim), "keep me");
  EXPECT_FALSE(fs::is_symlink(dir / "out.txt"));
  EXPECT_EQ(slurp(dir / "out.txt"), "new");
  fs::remove_all(dir);
}

// `-o /dev/null` once replaced /dev/null with a regular file (run as root, the rename
// succeeded): a FIFO or character device is written into, never renamed over.
TEST(AtomicFile, AFifoIsWrittenIntoNotReplaced) {
  const fs::path dir = freshDir("fifo");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Opened for reading first (without blocking), so the writer's open does not wait; the
  // bytes wait in the pipe's buffer.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  writeFileAtomically(fifo.string(), "through the pipe");
  char got[64] = {};
  const ssize_t n = ::read(reader, got, sizeof got);
  ::close(reader);
  EXPECT_EQ(std::string(got, size_t(std::max<ssize_t>(n, 0))), "through the pipe");
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(entries(dir), 1u);  // no temporary file beside it
  // A video is renamed into place, so it refuses one.
  try {
    createTemporaryBeside(fifo.string());
    ADD_FAILURE() << "a FIFO taken as a video's target";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(entries(dir), 1u);
  fs::remove_all(dir);
}

TEST(AtomicFile, SameExistingFileSeesThroughSpellingsAndLinks) {
  const fs::path dir = freshDir("same");
  const fs::path a = dir / "a";
  std::ofstream(a) << "a";
  std::ofstream(dir / "b") << "b";
  fs::create_symlink(a, dir / "link");
  EXPECT_TRUE(sameExistingFile(a.string(), (dir / "." / "a").string()));
  EXPECT_TRUE(sameExistingFile(a.string(), (dir / "link").string()));
  EXPECT_FALSE(sameExistingFile(a.string(), (dir / "b").string()));
  EXPECT_FALSE(sameExistingFile(a.string(), (dir / "none").string()));
  fs::remove_all(dir);
}

TEST(AtomicFile, PngAndTransferFunctionWritersUseIt) {
  const fs::path dir = freshDir("writers");
  Image8 img;
  img.width = 3;
  img.height = 2;
  img.channels = 3;
  img.pixels.assign(18, 7);
  writePng((dir / "x.png").string(), img);
  EXPECT_EQ(readPng((dir / "x.png").string()).width, 3);
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {1.0, 0.5}};
  saveTransferFunction((dir / "t.tf.json").string(), tf);
  EXPECT_EQ(loadTransferFunction((dir / "t.tf.json").string()), tf);
  EXPECT_EQ(entries(dir), 2u);
  EXPECT_THROW(writePng((dir / "nope" / "x.png").string(), img), std::runtime_error);
  EXPECT_THROW(saveTransferFunction((dir / "nope" / "t.json").string(), tf), std::runtime_error);
  EXPECT_EQ(entries(dir), 2u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ewa
