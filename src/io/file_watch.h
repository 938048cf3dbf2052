// FileWatch: notices that a file (or a folder's listing) changed and then held still, so a
// viewer can reload a volume a simulation or a scanner rewrites (the window's "reload when the
// file changes", --watch). No UI; the caller passes the time.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace ewa {

// What is compared: the modification time and size (a folder: its own time, which changes when
// files are added, removed or renamed in it). Nothing when the path cannot be read.
struct FileStamp {
  int64_t modified = 0;  // file clock ticks
  uintmax_t size = 0;
  bool operator==(const FileStamp& o) const { return modified == o.modified && size == o.size; }
  bool operator!=(const FileStamp& o) const { return !(*this == o); }
};
std::optional<FileStamp> fileStamp(const std::string& path);

class FileWatch {
 public:
  // Watches `path` from now (its present stamp is the one loaded); "" stops watching.
  void watch(const std::string& path);
  const std::string& path() const { return path_; }
  // Called as often as wanted with the time in seconds; looks at the file at most every
  // `intervalSeconds`. True once, when the file differs from the stamp watched and has kept
  // its new stamp over one more look (a file still being written is not taken half way); the
  // new stamp is then the one watched. A file that is missing for a while (rewritten by rename)
  // counts as changed when it is back.
  bool changed(double nowSeconds, double intervalSeconds = 0.5);

 private:
  std::string path_;
  std::optional<FileStamp> loaded_;   // the stamp of what is on screen
  std::optional<FileStamp> pending_;  // a new stamp seen once, waiting to hold still
  double lastLook_ = -1e300;
};

}  // namespace ewa
