// Finds an OME-Zarr image's array for a pyramid level and the roles and spacing of its axes.
#include "io/zarr_image.h"

#include <filesystem>
#include <optional>

#include "io/format_loaders.h"
#include "io/length_unit.h"
#include "io/load_failure.h"
#include "io/side_file.h"
#include "io/volume_loader.h"

namespace ewa {

namespace {

namespace fs = std::filesystem;

// Metadata files are a few kilobytes; a megabyte is far above any real one.
constexpr uint64_t kMaxMetadataBytes = 1 << 20;

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::string readMetadata(const std::string& userPath, const fs::path& file) {
  try {
    return readSideFile(file.string(), file.filename().string(), kMaxMetadataBytes);
  } catch (const LoadError&) {
    throw;
  } catch (const std::exception& e) {
    failLoad(userPath, problemText(e));
  }
}

bool isMetadataName(const std::string& name) {
  return name == ".zattrs" || name == ".zarray" || name == ".zgroup";
}

// The folder the user means: the named folder, or the folder of a named metadata file.
fs::path imageFolder(const std::string& path) {
  const fs::path p(path);
  if (isMetadataName(p.filename().string())) return p.parent_path().empty() ? "." : p.parent_path();
  return p;
}

// Axes as OME-NGFF names them, or, without names (versions 0.1 and 0.2, or a bare array),
// the order OME-NGFF writes: t, c, z, y, x with the leading ones left out.
std::vector<ZarrAxis> axesOf(const std::string& path, const std::vector<ZarrAxis>& named,
                             size_t rank) {
  if (!named.empty()) {
    if (named.size() != rank)
      failLoad(path, "multiscales names " + std::to_string(named.size()) +
                         " axes for an array of " + std::to_string(rank));
    return named;
  }
  static const ZarrAxis kDefault[] = {{"t", "time", ""},
                                      {"c", "channel", ""},
                                      {"z", "space", ""},
                                      {"y", "space", ""},
                                      {"x", "space", ""}};
  if (rank < 2 || rank > 5)
    failLoad(path, "an array of " + std::to_string(rank) +
                       " axes without OME-NGFF axes is not read (2 to 5: [t,] [c,] [z,] y, x)");
  // Four axes without names: OME-NGFF's channel, z, y, x (a time series names its axes).
  return std::vector<ZarrAxis>(std::end(kDefault) - rank, std::end(kDefault));
}

void assignAxes(const std::string& path, ZarrImage& image, const std::vector<ZarrAxis>& axes) {
  std::vector<int> space;
  for (size_t a = 0; a < axes.size(); ++a) {
    const ZarrAxis& axis = axes[a];
    const std::string what = "axis " + quoteText(axis.name) + " of type " + quoteText(axis.type);
    if (axis.type == "space") {
      space.push_back(int(a));
    } else if (axis.type == "time" || axis.type == "channel") {
      int& role = axis.type == "time" ? image.timeAxis : image.channelAxis;
      if (role >= 0) failLoad(path, "has two axes of type " + quoteText(axis.type));
      if (!space.empty())
        failLoad(path, what + " follows a space axis (time and channel axes come first)");
      if (image.meta.shape[a] > (1 << 30))
        failLoad(path, what + " has " + std::to_string(image.meta.shape[a]) + " entries");
      role = int(a);
    } else {
      failLoad(path, what + " is not read (space, time or channel)");
    }
  }
  if (space.size() < 2 || space.size() > 3)
    failLoad(path, "has " + std::to_string(space.size()) + " space axes (2 or 3 are read)");
  // OME-NGFF orders space axes z, y, x: the last varies fastest, as a Volume's x does.
  for (size_t i = 0; i < space.size(); ++i) image.spaceAxes[i] = space[space.size() - 1 - i];
}

void placeVoxels(ZarrImage& image, const std::vector<ZarrAxis>& axes, const ZarrLevel* level,
                 const ZarrArrayMeta* full) {
  std::string unit;
  bool oneUnit = true;
  for (int i = 0; i < 3; ++i) {
    const int a = image.spaceAxes[size_t(i)];
    if (a < 0) continue;
    if (level && !level->scale.empty()) {
      image.spacing[i] = level->scale[size_t(a)];
      image.origin[i] = level->translation[size_t(a)];
    } else if (full) {
      // No scale given (OME-NGFF before 0.4): a coarser level's voxels span the full one's.
      image.spacing[i] = double(full->shape[size_t(a)]) / double(image.meta.shape[size_t(a)]);
    }
    const std::string u = lengthUnitName(axes[size_t(a)].unit);
    if (i > 0 && u != unit) oneUnit = false;
    unit = u;
  }
  if (oneUnit) image.unit = unit;
}

}  // namespace

std::array<int64_t, 3> ZarrImage::dims() const {
  std::array<int64_t, 3> d{1, 1, 1};
  for (size_t i = 0; i < 3; ++i)
    if (spaceAxes[i] >= 0) d[i] = meta.shape[size_t(spaceAxes[i])];
  return d;
}

bool isZarrPath(const std::string& path) {
  const fs::path p(path);
  if (isMetadataName(p.filename().string())) return isFile(p);
  std::error_code ec;
  if (!fs::is_directory(p, ec)) return false;
  return isFile(p / ".zattrs") || isFile(p / ".zarray") || isFile(p / ".zgroup");
}

ZarrImage openZarrImage(const std::string& path, int level, DataFileScope scope) {
  fs::path folder = imageFolder(path);
  std::optional<ZarrMultiscale> multiscale;
  ZarrImage image;
  image.path = path;
  if (isFile(folder / ".zattrs")) {
    image.attributes = (folder / ".zattrs").string();
    multiscale = parseZarrMultiscales(path, readMetadata(path, folder / ".zattrs"));
    // bioformats2raw writes a group whose images are 0, 1, ...: open the first.
    if (!multiscale && isFile(folder / "0" / ".zattrs") && !isFile(folder / ".zarray")) {
      const fs::path inner = folder / "0" / ".zattrs";
      multiscale = parseZarrMultiscales(path, readMetadata(path, inner));
      if (multiscale) {
        folder /= "0";
        image.attributes = inner.string();
        image.notes.push_back("the first image (\"0\") of the group");
      }
    }
  }
  std::vector<ZarrAxis> named;
  const ZarrLevel* chosen = nullptr;
  std::optional<ZarrArrayMeta> full;
  if (multiscale) {
    image.levels = int(multiscale->levels.size());
    if (level < 0 || level >= image.levels)
      failLoad(path, "--level " + std::to_string(level) + " is out of range (the image has " +
                         std::to_string(image.levels) + " level" + (image.levels == 1 ? "" : "s") +
                         ", 0 to " + std::to_string(image.levels - 1) + ")");
    chosen = &multiscale->levels[size_t(level)];
    image.levelName = chosen->path;
    image.arrayFolder = (folder / chosen->path).string();
    named = multiscale->axes;
    if (chosen->scale.empty() && level > 0) {
      const fs::path first = folder / multiscale->levels[0].path / ".zarray";
      full = parseZarrArray(first.string(), readMetadata(path, first));
    }
  } else if (isFile(folder / ".zarray")) {
    if (level != 0)
      failLoad(path, "--level " + std::to_string(level) +
                         " is out of range (a Zarr array without multiscales has level 0 alone)");
    image.attributes = (folder / ".zarray").string();
    image.arrayFolder = folder.string();
  } else {
    failLoad(path, isFile(folder / ".zgroup") || isFile(folder / ".zattrs")
                       ? "a Zarr group without OME-NGFF multiscales (open one of its arrays' "
                         "folders, which hold a .zarray)"
                       : "not a Zarr image (no .zattrs, .zgroup or .zarray)");
  }
  image.level = level;
  checkDataFileScope(image.attributes, image.arrayFolder, scope);
  const fs::path zarray = fs::path(image.arrayFolder) / ".zarray";
  if (!isFile(zarray)) failLoad(path, "level " + quoteText(image.levelName) + " has no .zarray");
  image.meta = parseZarrArray(zarray.string(), readMetadata(path, zarray));
  const std::vector<ZarrAxis> axes = axesOf(path, named, image.meta.shape.size());
  assignAxes(path, image, axes);
  placeVoxels(image, axes, chosen, full ? &*full : nullptr);
  if (image.levels > 1)
    image.notes.push_back("pyramid level " + std::to_string(level) + " of " +
                          std::to_string(image.levels) + " (--level; 0 is full resolution)");
  return image;
}

}  // namespace ewa
