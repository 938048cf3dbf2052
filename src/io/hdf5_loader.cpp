// HDF5 files (.h5, .hdf5) through Debian's serial libhdf5: one 3D dataset, read as a hyperslab.
#include <hdf5.h>

#include <cmath>
#include <new>
#include <string>
#include <vector>

#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/region_read.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

// Datasets looked at when searching for the 3D ones: far above any real file's count, and a
// bound on the time a file of millions of tiny objects can take.
constexpr size_t kMaxObjectsVisited = 100000;

// Closes an HDF5 handle when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  void reset(hid_t id) {
    if (id_ >= 0) close_(id_);
    id_ = id;
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// The innermost message of the library's error stack ("can't open object"), for our line.
herr_t innermost(unsigned, const H5E_error2_t* e, void* out) {
  if (e->desc && *e->desc) *static_cast<std::string*>(out) = e->desc;
  return 0;
}

std::string libraryProblem() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, innermost, &text);
  H5Eclear2(H5E_DEFAULT);
  return text.empty() ? "" : " (" + quoteText(text, 120) + ")";
}

// The library prints its error stack to stderr by default; ewaview says one line instead.
void quietLibrary() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

struct DatasetList {
  std::vector<std::string> threeD;
  size_t visited = 0;
};

herr_t listDataset(hid_t file, const char* name, const H5O_info_t* info, void* data) {
  auto* list = static_cast<DatasetList*>(data);
  if (++list->visited > kMaxObjectsVisited) return 1;  // stop: enough looked at
  if (info->type != H5O_TYPE_DATASET) return 0;
  const Handle dataset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) return 0;
  const Handle space(H5Dget_space(dataset.get()), H5Sclose);
  if (space.valid() && H5Sget_simple_extent_ndims(space.get()) == 3)
    list->threeD.push_back(std::string("/") + name);
  return 0;
}

std::string listText(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size() && i < 20; ++i) s += (i ? ", " : "") + quoteText(names[i]);
  if (names.size() > 20) s += ", ...";
  return s.empty() ? "none" : s;
}

std::vector<std::string> threeDDatasets(const std::string& path, hid_t file) {
  DatasetList list;
  if (H5Ovisit(file, H5_INDEX_NAME, H5_ITER_INC, listDataset, &list) < 0)
    failLoad(path, "cannot list the file's datasets" + libraryProblem());
  return list.threeD;
}

// An open 3D dataset: what it holds and where its voxels sit.
struct Dataset {
  std::string name;
  std::array<int64_t, 3> dims{0, 0, 0};  // x, y, z (the file's last axis is x)
  FileScalar type = FileScalar::UInt8;
  hid_t memoryType = -1;  // the native type HDF5 converts the file's values to
  glm::dvec3 spacing{1.0};
  std::string unit;
  std::vector<std::string> notes;
};

bool scalarType(hid_t type, FileScalar& out, hid_t& memory) {
  const H5T_class_t kind = H5Tget_class(type);
  const size_t size = H5Tget_size(type);
  if (kind == H5T_FLOAT) {
    if (size == 4) return out = FileScalar::Float32, memory = H5T_NATIVE_FLOAT, true;
    if (size == 8) return out = FileScalar::Float64, memory = H5T_NATIVE_DOUBLE, true;
    return false;
  }
  if (kind != H5T_INTEGER) return false;
  const bool isSigned = H5Tget_sign(type) == H5T_SGN_2;
  switch (size) {
    case 1:
      out = isSigned ? FileScalar::Int8 : FileScalar::UInt8;
      memory = isSigned ? H5T_NATIVE_INT8 : H5T_NATIVE_UINT8;
      return true;
    case 2:
      out = isSigned ? FileScalar::Int16 : FileScalar::UInt16;
      memory = isSigned ? H5T_NATIVE_INT16 : H5T_NATIVE_UINT16;
      return true;
    case 4:
      out = isSigned ? FileScalar::Int32 : FileScalar::UInt32;
      memory = isSigned ? H5T_NATIVE_INT32 : H5T_NATIVE_UINT32;
      return true;
    case 8:
      out = isSigned ? FileScalar::Int64 : FileScalar::UInt64;
      memory = isSigned ? H5T_NATIVE_INT64 : H5T_NATIVE_UINT64;
      return true;
    default:
      return false;
  }
}

// Three positive numbers in attribute `name` of the dataset, in the dataset's axis order
// (z, y, x), as x, y, z; false when it is absent, and a note when it is there but unusable.
bool spacingAttribute(hid_t dataset, const char* name, glm::dvec3& out,
                      std::vector<std::string>& notes) {
  if (H5Aexists(dataset, name) <= 0) return false;
  const Handle attribute(H5Aopen(dataset, name, H5P_DEFAULT), H5Aclose);
  const Handle space(attribute.valid() ? H5Aget_space(attribute.get()) : -1, H5Sclose);
  const Handle type(attribute.valid() ? H5Aget_type(attribute.get()) : -1, H5Tclose);
  const H5T_class_t kind = type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
  double v[3] = {0, 0, 0};
  const bool read = space.valid() && H5Sget_simple_extent_npoints(space.get()) == 3 &&
                    (kind == H5T_INTEGER || kind == H5T_FLOAT) &&
                    H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, v) >= 0;
  for (const double x : v) {
    if (read && std::isfinite(x) && x > 0) continue;
    notes.push_back(std::string("attribute ") + name +
                    " is not three positive numbers: spacing 1 assumed");
    H5Eclear2(H5E_DEFAULT);
    return false;
  }
  out = glm::dvec3(v[2], v[1], v[0]);
  return true;
}

Dataset describe(const std::string& path, hid_t file, const std::string& wanted, Handle& handle) {
  Dataset d;
  if (wanted.empty()) {
    const std::vector<std::string> found = threeDDatasets(path, file);
    if (found.size() != 1)
      failLoad(path, found.empty() ? "holds no 3D dataset"
                                   : "holds several 3D datasets; choose one with --dataset: " +
                                         listText(found));
    d.name = found[0];
  } else {
    d.name = wanted;
  }
  // H5Lexists of a path whose middle part is missing fails rather than saying no; either way
  // the dataset is not there.
  const htri_t exists = H5Lexists(file, d.name.c_str(), H5P_DEFAULT);
  if (exists > 0) handle.reset(H5Dopen2(file, d.name.c_str(), H5P_DEFAULT));
  if (exists <= 0 || !handle.valid()) {
    H5Eclear2(H5E_DEFAULT);
    failLoad(path, "has no dataset " + quoteText(d.name) +
                       " (3D datasets: " + listText(threeDDatasets(path, file)) + ")");
  }
  const Handle space(H5Dget_space(handle.get()), H5Sclose);
  const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank != 3)
    failLoad(path, "dataset " + quoteText(d.name) + " has " + std::to_string(rank) +
                       " dimensions; 3D datasets are read (" +
                       listText(threeDDatasets(path, file)) + ")");
  hsize_t dims[3] = {0, 0, 0};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  for (int i = 0; i < 3; ++i) {
    if (dims[2 - i] > hsize_t(INT64_MAX)) failLoad(path, "dataset sizes are too large");
    d.dims[size_t(i)] = int64_t(dims[2 - i]);
  }
  const Handle type(H5Dget_type(handle.get()), H5Tclose);
  if (!type.valid() || !scalarType(type.get(), d.type, d.memoryType))
    failLoad(path, "dataset " + quoteText(d.name) +
                       " holds values that are not read (integers of 8 to 64 bits, float32, "
                       "float64)");
  // ilastik's and BigDataViewer's element_size_um, else a plain "spacing" (no unit).
  if (spacingAttribute(handle.get(), "element_size_um", d.spacing, d.notes))
    d.unit = "\xC2\xB5m";
  else
    spacingAttribute(handle.get(), "spacing", d.spacing, d.notes);
  return d;
}

template <typename F>
auto withFile(const std::string& path, F&& f) -> decltype(f(hid_t())) {
  regularFileSize(path);  // missing files, folders and FIFOs say so in ewaview's words
  quietLibrary();
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    failLoad(path, "not an HDF5 file (no HDF5 signature)");
  }
  // Read only, so no lock is needed: without one, the file opens on file systems that have no
  // locks (some parallel ones) and while a writer holds it, as every process of a run reads it.
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (access.valid()) H5Pset_file_locking(access.get(), false, true);
  const Handle file(
      H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.valid() ? access.get() : H5P_DEFAULT), H5Fclose);
  if (!file.valid()) failLoad(path, "cannot open the HDF5 file" + libraryProblem());
  try {
    return f(file.get());
  } catch (const std::bad_alloc&) {
    failLoad(path, "out of memory");
  }
}

Volume readRegion(const std::string& path, hid_t file, const std::string& wanted,
                  const VoxelRegion* region) {
  Handle handle(-1, H5Dclose);
  const Dataset d = describe(path, file, wanted, handle);
  VoxelRegion box;
  box.hi = d.dims;
  if (region) box = *region;
  for (size_t i = 0; i < 3; ++i)
    if (box.lo[i] < 0 || box.lo[i] >= box.hi[i] || box.hi[i] > d.dims[i])
      failLoad(path, "region is empty or not inside the dataset's " + std::to_string(d.dims[0]) +
                         " x " + std::to_string(d.dims[1]) + " x " + std::to_string(d.dims[2]));
  VolumeLayout layout;
  for (size_t i = 0; i < 3; ++i) layout.dims[i] = box.hi[i] - box.lo[i];
  layout.type = d.type;
  const uint64_t bytes = dataByteCount(path, layout.dims, layout.type);
  std::vector<uint8_t> data(bytes);
  // The file's axes are z, y, x: the hyperslab's corner and counts in that order.
  const hsize_t start[3] = {hsize_t(box.lo[2]), hsize_t(box.lo[1]), hsize_t(box.lo[0])};
  const hsize_t count[3] = {hsize_t(layout.dims[2]), hsize_t(layout.dims[1]),
                            hsize_t(layout.dims[0])};
  const Handle fileSpace(H5Dget_space(handle.get()), H5Sclose);
  const Handle memorySpace(H5Screate_simple(3, count, nullptr), H5Sclose);
  if (!fileSpace.valid() || !memorySpace.valid() ||
      H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
      H5Dread(handle.get(), d.memoryType, memorySpace.get(), fileSpace.get(), H5P_DEFAULT,
              data.data()) < 0)
    failLoad(path, "cannot read dataset " + quoteText(d.name) + libraryProblem());
  layout.spacing = d.spacing;
  for (int i = 0; i < 3; ++i) layout.origin[i] = double(box.lo[size_t(i)]) * d.spacing[i];
  layout.unit = d.unit;
  layout.notes = d.notes;
  layout.notes.push_back("dataset " + quoteText(d.name));
  return makeVolume(path, layout, std::move(data));
}

}  // namespace

Volume loadHdf5(const std::string& path, const std::string& dataset) {
  return withFile(path, [&](hid_t file) { return readRegion(path, file, dataset, nullptr); });
}

RegionSourceShape hdf5Shape(const std::string& path, const std::string& dataset) {
  return withFile(path, [&](hid_t file) {
    Handle handle(-1, H5Dclose);
    const Dataset d = describe(path, file, dataset, handle);
    RegionSourceShape shape;
    shape.dims = d.dims;
    shape.spacing = d.spacing;
    shape.type = d.type;
    return shape;
  });
}

Volume loadHdf5Region(const std::string& path, const std::string& dataset, const VoxelRegion& box) {
  return withFile(path, [&](hid_t file) { return readRegion(path, file, dataset, &box); });
}

}  // namespace ewa
