// FileWatch: a change is reported once, after it held still for one more look.
#include "io/file_watch.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace ewa {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ewa_file_watch_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// Moves the file's time on by `seconds`, as a later write would.
void touch(const fs::path& p, int seconds) {
  fs::last_write_time(p, fs::last_write_time(p) + std::chrono::seconds(seconds));
}

TEST(FileWatch, ReportsAChangeOnceItHoldsStill) {
  const fs::path f = scratch("still") / "v.nrrd";
  write(f, "one");
  FileWatch w;
  w.watch(f.string());
  EXPECT_FALSE(w.changed(0.0));
  EXPECT_FALSE(w.changed(1.0));  // unchanged
  write(f, "three");
  touch(f, 5);
  EXPECT_FALSE(w.changed(1.2));  // within the interval: not looked at
  EXPECT_FALSE(w.changed(2.0));  // seen once
  write(f, "three, longer");     // still being written
  touch(f, 6);
  EXPECT_FALSE(w.changed(3.0));  // another new stamp: look again
  EXPECT_TRUE(w.changed(4.0));   // held still
  EXPECT_FALSE(w.changed(5.0));  // reported once
}

TEST(FileWatch, AFileMissingForAWhileCountsWhenItIsBack) {
  const fs::path dir = scratch("missing");
  const fs::path f = dir / "v.raw";
  write(f, "abc");
  FileWatch w;
  w.watch(f.string());
  fs::remove(f);
  EXPECT_FALSE(w.changed(1.0));
  EXPECT_FALSE(w.changed(2.0));
  write(f, "abcd");
  EXPECT_FALSE(w.changed(3.0));
  EXPECT_TRUE(w.changed(4.0));
}

TEST(FileWatch, AFolderChangesWhenAFileIsAddedAndNothingIsWatchedWithoutAPath) {
  const fs::path dir = scratch("folder");
  write(dir / "s1.png", "x");
  FileWatch w;
  w.watch(dir.string());
  write(dir / "s2.png", "y");
  fs::last_write_time(dir, fs::last_write_time(dir) + std::chrono::seconds(3));
  EXPECT_FALSE(w.changed(1.0));
  EXPECT_TRUE(w.changed(2.0));
  w.watch("");
  EXPECT_FALSE(w.changed(10.0));
  EXPECT_FALSE(fileStamp((dir / "none").string()));
}

}  // namespace
}  // namespace ewa
