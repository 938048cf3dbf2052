// Removing scratch folders (unpacked archives) when the process is ended by a signal.
#pragma once

#include <string>

namespace ewa {

// While registered, `folder` is removed if SIGINT, SIGTERM, SIGHUP or SIGQUIT ends the process
// (the signal then ends it as it would have). SIGKILL cannot be caught: what it leaves is
// removed by the next ewaview that unpacks an archive (extractArchive). At most 16 folders are
// registered at once; more are left to that later clean-up. Thread-safe.
void registerScratchFolder(const std::string& folder);
void unregisterScratchFolder(const std::string& folder);

}  // namespace ewa
