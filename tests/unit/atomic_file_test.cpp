// writeFileAtomically and the writers built on it: whole files or nothing, no temporary files
// left, no links followed, inputs never replaced.
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

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
