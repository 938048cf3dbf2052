// loadVolume: picks the loader by file extension and keeps every failure a one-line LoadError.
#include "io/volume_loader.h"

#include <filesystem>
#include <new>
#include <sstream>

#include "io/archive_cache.h"
#include "io/archive_extract.h"
#include "io/file_bytes.h"
#include "io/file_listing.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

// True when a file of the folder that is no slice image or TIFF is DICOM (or a CD's DICOMDIR); the
// first thousand such files are looked into.
bool holdsDicom(const std::string& folder) {
  std::error_code ec;
  int looked = 0;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end && looked < 1000;
       it.increment(ec)) {
    const std::string file = it->path().string();
    std::error_code statError;
    if (!it->is_regular_file(statError) || hasExtension(file, sliceImageExtensions()) ||
        hasExtension(file, {".tif", ".tiff"}))
      continue;
    ++looked;
    if (toLower(it->path().filename().string()) == "dicomdir" || looksLikeDicom(file)) return true;
  }
  return false;
}

// A folder holds a TIFF stack, a stack of other images (PNG, JPEG, ...) or a DICOM series (also
// a CD's tree of folders, which may hold a viewer's images or TIFF exports beside it: any DICOM
// file wins).
Volume loadFolder(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  bool tiff = false, images = false, others = false;
  for (std::filesystem::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().string();
    if (hasExtension(file, {".tif", ".tiff"}))
      tiff = true;
    else if (hasExtension(file, sliceImageExtensions()))
      images = true;
    else
      others = true;
  }
  if (ec) failLoad(path, "cannot list the folder (" + ec.message() + ")");
  const bool dicom = others && (tiff || images) && holdsDicom(path);
  if (tiff && !dicom) return loadTiff(path, options.channel, options.frame);
  if (images && !dicom) return loadImageStack(path, options.channel);
  return loadDicom(path, options.series, options.channel, options.frame);
}

Volume loadByExtension(const std::string& path, const LoadOptions& options, ArchiveCache* archives);

// An archive opens what it holds (archiveVolumePath); errors name the entry, not the scratch
// folder, which is gone once the volume is in memory.
Volume loadArchive(const std::string& path, const LoadOptions& options, ArchiveCache* archives) {
  const std::shared_ptr<const ExtractedArchive> held =
      archives ? archives->unpack(path)
               : std::make_shared<const ExtractedArchive>(extractArchive(path));
  const ExtractedArchive& unpacked = *held;
  const std::string inside = archiveVolumePath(unpacked, path);
  try {
    Volume volume = loadByExtension(inside, options, nullptr);
    const std::string what = unpacked.relative(inside);
    volume.addNote("unpacked " + std::to_string(unpacked.files) +
                   " files from the archive and opened " +
                   (what.empty() ? std::string("its top folder") : quoteText(what, 200)));
    return volume;
  } catch (const LoadError& e) {
    failLoad(path, unpacked.relative(e.what()));
  }
}

Volume loadByExtension(const std::string& path, const LoadOptions& options,
                       ArchiveCache* archives) {
  std::error_code ec;
  // A Zarr image is a folder (or its metadata file) whatever its name.
  if (isZarrPath(path) ||
      (hasExtension(path, {".zarr"}) && std::filesystem::is_directory(path, ec)))
    return loadZarr(path, options.level, options.frame, options.channel, options.dataFiles);
  if (std::filesystem::is_directory(path, ec)) return loadFolder(path, options);
  // Missing files get the same message whatever their extension.
  regularFileSize(path);
  const std::string name = toLower(std::filesystem::path(path).filename().string());
  const std::string ext = toLower(std::filesystem::path(path).extension().string());
  const bool gz = ext == ".gz";
  const std::string inner =
      gz ? toLower(std::filesystem::path(name.substr(0, name.size() - 3)).extension().string())
         : ext;
  if (ext == ".nrrd" || ext == ".nhdr")
    return loadNrrd(path, options.frame, options.channel, options.dataFiles);
  if (ext == ".mhd" || ext == ".mha")
    return loadMetaImage(path, options.channel, options.dataFiles);
  if (ext == ".dat") return loadDat(path, options.dataFiles);
  if (ext == ".vti") return loadVti(path, options.channel);
  if (ext == ".vtk") return loadVtkLegacy(path, options.channel);
  if (inner == ".nii" || inner == ".hdr" || inner == ".img")
    return loadNifti(path, options.frame, options.channel);
  if (ext == ".slc") return loadSlc(path);
  if (ext == ".h5" || ext == ".hdf5") return loadHdf5(path, options.dataset);
  if (ext == ".mrc" || ext == ".mrcs" || ext == ".map" || ext == ".ccp4" || ext == ".rec")
    return loadMrc(path);
  if (ext == ".tif" || ext == ".tiff") return loadTiff(path, options.channel, options.frame);
  if (hasExtension(path, sliceImageExtensions())) return loadImageStack(path, options.channel);
  if (ext == ".ome" || hasExtension(path, {".ome.xml"}))
    return loadOmeCompanion(path, options.channel, options.frame);
  if (isArchiveName(path)) return loadArchive(path, options, archives);
  if (ext == ".dcm" || ext == ".ima" || looksLikeDicom(path))
    return loadDicom(path, options.series, options.channel, options.frame);
  failLoad(path,
           "unknown volume file extension " + quoteText(ext) +
               " (supported: .nrrd .nhdr .mhd .mha .dat .vti .vtk .nii .nii.gz .hdr .img .dcm "
               ".tif .tiff .ome .slc .mrc .map .rec .h5 .hdf5, .zarr folders, DICOM files and "
               "folders, folders of .png "
               ".jpg .bmp .pgm slices, archives of them: .zip .tar .tar.gz .7z ...; raw files "
               "need their dimensions and type given)");
}

// Errors about a data file named by the header still start with the path the caller gave.
[[noreturn]] void rethrowWithPath(const std::string& path, const std::string& message) {
  if (message.compare(0, path.size() + 2, path + ": ") == 0) throw LoadError(oneLine(message));
  failLoad(path, message);
}

}  // namespace

bool mayHoldZarrLevels(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return true;
  return isZarrPath(path) ||
         (hasExtension(path, {".zarr"}) && std::filesystem::is_directory(path, ec)) ||
         (!std::filesystem::is_directory(path, ec) && isArchiveName(path));
}

void overrideSpacing(const std::string& path, Volume& volume, const glm::dvec3& spacing) {
  const glm::dvec3 file = volume.spacing();
  try {
    volume.setSpacing(spacing);
  } catch (const std::invalid_argument&) {
    failLoad(path, "--spacing must be positive and finite");
  }
  const auto text = [](const glm::dvec3& v) {
    std::ostringstream out;
    out << v.x << ", " << v.y << ", " << v.z;
    return out.str();
  };
  volume.addNote("spacing " + text(spacing) + " from --spacing (the file's: " + text(file) + ")");
}

Volume loadVolume(const std::string& path, const LoadOptions& options, ArchiveCache* archives) {
  try {
    Volume volume = loadByExtension(path, options, archives);
    if (options.spacing) overrideSpacing(path, volume, *options.spacing);
    return volume;
  } catch (const LoadError& e) {
    rethrowWithPath(path, e.what());
  } catch (const std::bad_alloc&) {
    failLoad(path, "out of memory");
  } catch (const std::exception& e) {
    rethrowWithPath(path, e.what());
  }
}

}  // namespace ewa
