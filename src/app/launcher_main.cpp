// ewaview's launcher: starts the viewer (libexec/ewaview beside it) with glibc already asked for
// huge pages, so that the viewer, which loads some 180 shared libraries before main(), need not
// load them twice by running itself again for the tunable (heap_tuning.h, askForHugePages).
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "app/heap_tuning.h"

int main(int argc, char** argv) {
  (void)argc;
  const std::string tunables = ewa::hugePageTunables(std::getenv("GLIBC_TUNABLES"));
  if (!tunables.empty()) setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
  // The launcher's own file, links followed: a link to it elsewhere still finds the viewer.
  std::error_code error;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) self = std::filesystem::absolute(argv[0], error);
  const std::string viewer = (self.parent_path() / "libexec" / "ewaview").string();
  execv(viewer.c_str(), argv);  // argv[0] stays the launcher's, for the viewer's messages
  std::cerr << "ewaview: cannot start the viewer " << viewer << ": " << std::strerror(errno)
            << "\n";
  return 127;
}
