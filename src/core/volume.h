// Volume: a 3D scalar grid kept in its native type, placed in world space like VTK image data.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ewa {

enum class ScalarType { UInt8, Int16, UInt16, Float32 };

// One of the volumes a file or folder holds besides others (a DICOM folder's series and the
// parts split off one): what --series names it, and a line to choose it by.
struct SeriesChoice {
  std::string id;     // the --series argument: a SeriesInstanceUID, or UID#2, ...
  std::string label;  // "120 slices, AX T1 (open)"
  bool open = false;  // the one this volume is
};

// Bytes per value of each scalar type. Inline (as valueAt is): classification calls them for
// every voxel and its neighbours, and out of line the calls cost more than the reads.
inline size_t scalarSize(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Float32:
      return 4;
  }
  return 1;
}

// "uint8", "int16", "uint16", "float32".
const char* scalarName(ScalarType type);

// A box in voxel index coordinates (low and high corners).
struct DataBox {
  glm::dvec3 low{0.0};
  glm::dvec3 high{0.0};
};

class Volume {
 public:
  Volume() = default;
  // Takes ownership of `bytes`, which must hold dims product * scalarSize(type) bytes in
  // x-fastest order, native endianness. Computes the value range and the histogram.
  // Throws std::invalid_argument when the sizes do not agree.
  Volume(std::array<int64_t, 3> dims, glm::dvec3 spacing, glm::dvec3 origin, ScalarType type,
         std::vector<uint8_t> bytes);

  const std::array<int64_t, 3>& dims() const { return dims_; }
  const glm::dvec3& spacing() const { return spacing_; }
  // Replaces the spacing (a file without one, or a wrong one: --spacing). Throws
  // std::invalid_argument unless every component is positive and finite.
  void setSpacing(const glm::dvec3& spacing);
  const glm::dvec3& origin() const { return origin_; }
  // Direction cosines: column a is the world direction of data axis a (identity by default).
  // Loaders leave it a rotation (see volume_orientation.h), so renderers can draw the volume in
  // its own frame under a rigidly moved camera.
  const glm::dmat3& direction() const { return direction_; }
  // True when the axes are patient axes (LPS: x left, y posterior, z superior), from DICOM,
  // NIfTI or a NRRD/MetaImage anatomical space: axis views are then labelled anatomically.
  bool patientFrame() const { return patientFrame_; }
  void setDirection(const glm::dmat3& direction, bool patientFrame);
  // The unit of world lengths (spacing, origin, distances), as the file gives it: "mm" (DICOM,
  // NIfTI), "µm", "m", a NRRD's "space units"; "" when the file does not say.
  const std::string& unit() const { return unit_; }
  void setUnit(std::string unit) { unit_ = std::move(unit); }
  // Which of the file's volumes this is (a 4D NIfTI's time points, a DICOM series' volumes at
  // the same positions: --frame): frame() of frameCount(), 0 of 1 for a file of one volume.
  int frame() const { return frame_; }
  int frameCount() const { return frameCount_; }
  void setFrame(int frame, int count) { frame_ = frame, frameCount_ = count; }
  // Which channel of a multi-channel file this is (RGB DICOM, TIFF samples or an OME-TIFF's or
  // ImageJ hyperstack's channels, a 4D NRRD's colour axis: --channel): 0 of 1 for one channel.
  int channel() const { return channel_; }
  int channelCount() const { return channelCount_; }
  void setChannel(int channel, int count) { channel_ = channel, channelCount_ = count; }
  // The series the file's folder holds (DICOM), the open one marked; empty when it holds one.
  const std::vector<SeriesChoice>& seriesChoices() const { return seriesChoices_; }
  void setSeriesChoices(std::vector<SeriesChoice> choices) { seriesChoices_ = std::move(choices); }
  // Remarks from the loader for --info and the user: frames in the file, conversions, the other
  // series in a folder. Warnings start with "warning: " and are printed when the file opens.
  const std::vector<std::string>& notes() const { return notes_; }
  void addNote(std::string note) { notes_.push_back(std::move(note)); }
  // The files the volume was read from (the file opened, a header's data files, a series'
  // slices), so that writers can refuse to replace any of them (--output, --save-volume).
  const std::vector<std::string>& sourceFiles() const { return sourceFiles_; }
  void addSourceFile(std::string path) { sourceFiles_.push_back(std::move(path)); }
  ScalarType type() const { return type_; }
  int64_t voxelCount() const { return dims_[0] * dims_[1] * dims_[2]; }
  const std::vector<uint8_t>& bytes() const { return bytes_; }
  bool empty() const { return bytes_.empty(); }

  // Value of voxel (i,j,k) converted to double; NaN stays NaN.
  double value(int64_t i, int64_t j, int64_t k) const { return valueAt(index(i, j, k)); }
  double valueAt(int64_t linearIndex) const {
    const uint8_t* p = bytes_.data() + static_cast<size_t>(linearIndex) * scalarSize(type_);
    switch (type_) {
      case ScalarType::UInt8:
        return *p;
      case ScalarType::Int16: {
        int16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      case ScalarType::UInt16: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      case ScalarType::Float32: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
      }
    }
    return 0.0;
  }
  int64_t index(int64_t i, int64_t j, int64_t k) const { return i + dims_[0] * (j + dims_[1] * k); }

  // Finite value range over all voxels (NaN and infinities are skipped); {0,0} if none.
  double minValue() const { return range_[0]; }
  double maxValue() const { return range_[1]; }
  // Histogram of finite values over [minValue, maxValue] in histogramBins() bins.
  const std::vector<uint64_t>& histogram() const { return histogram_; }
  static constexpr int histogramBins() { return 256; }
  // Replaces the value range and histogram: a brick of a distributed volume takes the whole
  // volume's, agreed on by every process, so that its splats are quantized over the same range
  // and its default transfer function is the whole volume's. Throws std::invalid_argument
  // unless lo <= hi (finite) and `histogram` has histogramBins() bins.
  void setValueStatistics(double lo, double hi, std::vector<uint64_t> histogram);
  // The histogram of the finite values of the voxels low <= (i, j, k) < high over [lo, hi],
  // binned as histogram() bins (a brick's own voxels, without its ghosts, over the global
  // range: summed over the bricks it is the whole volume's histogram).
  std::vector<uint64_t> histogramOf(const std::array<int64_t, 3>& low,
                                    const std::array<int64_t, 3>& high, double lo, double hi) const;

  // Position of voxel (i,j,k) in the volume's own frame, where renderers draw it:
  // origin + (i,j,k) * spacing (the direction left out; see cameraInVolumeFrame).
  glm::dvec3 framePosition(double i, double j, double k) const;
  // World (patient) position of voxel (i,j,k): origin + D * ((i,j,k) * spacing).
  glm::dvec3 worldPosition(double i, double j, double k) const;
  // Axis-aligned bounds through the voxel centers in the volume's own frame.
  glm::dvec3 boundsMin() const { return origin_; }
  glm::dvec3 boundsMax() const;
  // Where the data's field ends, in voxel index coordinates: by default between the outermost
  // voxel centres (an axis one voxel thick: that voxel's extent, +-0.5), where a ray caster's
  // field ends; a coarser level of detail keeps its source's (downsampleVolume).
  DataBox indexDataBox() const;
  void setIndexDataBox(const DataBox& box);
  // Axis-aligned world bounds of the eight corner voxel centers (for framing the camera).
  glm::dvec3 worldBoundsMin() const;
  glm::dvec3 worldBoundsMax() const;

 private:
  void computeStatistics();

  std::array<int64_t, 3> dims_{0, 0, 0};
  glm::dvec3 spacing_{1.0};
  glm::dvec3 origin_{0.0};
  glm::dmat3 direction_{1.0};
  bool patientFrame_ = false;
  std::string unit_;
  int frame_ = 0, frameCount_ = 1;
  int channel_ = 0, channelCount_ = 1;
  std::vector<SeriesChoice> seriesChoices_;
  std::vector<std::string> notes_;
  std::vector<std::string> sourceFiles_;
  ScalarType type_ = ScalarType::UInt8;
  std::vector<uint8_t> bytes_;
  std::array<double, 2> range_{0.0, 0.0};
  std::vector<uint64_t> histogram_;
  std::optional<DataBox> dataBox_;  // else indexDataBox is the default
};

}  // namespace ewa
