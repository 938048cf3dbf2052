// loadVolume: picks the loader by file extension and keeps every failure a one-line LoadError.
#include "io/volume_loader.h"

#include <filesystem>
#include <new>

#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

Volume loadByExtension(const std::string& path) {
  // Missing files and folders get the same message whatever their extension.
  regularFileSize(path);
  const std::string ext = toLower(std::filesystem::path(path).extension().string());
  if (ext == ".nrrd" || ext == ".nhdr") return loadNrrd(path);
  if (ext == ".mhd" || ext == ".mha") return loadMetaImage(path);
  if (ext == ".dat") return loadDat(path);
  if (ext == ".vti") return loadVti(path);
  failLoad(path, "unknown volume file extension " + quoteText(ext) +
                     " (supported: .nrrd .nhdr .mhd .mha .dat .vti; raw files need their "
                     "dimensions and type given)");
}

// Errors about a data file named by the header still start with the path the caller gave.
[[noreturn]] void rethrowWithPath(const std::string& path, const std::string& message) {
  if (message.compare(0, path.size() + 2, path + ": ") == 0) throw LoadError(oneLine(message));
  failLoad(path, message);
}

}  // namespace

Volume loadVolume(const std::string& path) {
  try {
    return loadByExtension(path);
  } catch (const LoadError& e) {
    rethrowWithPath(path, e.what());
  } catch (const std::bad_alloc&) {
    failLoad(path, "out of memory");
  } catch (const std::exception& e) {
    rethrowWithPath(path, e.what());
  }
}

}  // namespace ewa
