// MRC and CCP4 maps (.mrc, .mrcs, .map, .ccp4, .rec): cryo-EM maps and tomograms (MRC2014).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <string>
#include <vector>

#include "io/byte_order.h"
#include "io/file_bytes.h"
#include "io/format_loaders.h"
#include "io/load_failure.h"
#include "io/volume_layout.h"

namespace ewa {

namespace {

constexpr uint64_t kHeaderBytes = 1024;
constexpr int32_t kImodStamp = 1146047817;  // "IMOD": IMOD's files say how they store bytes

class MrcHeader {
 public:
  MrcHeader(const std::vector<uint8_t>& bytes, bool big) : bytes_(bytes), big_(big) {}
  // Word `n` (1-based, as the format's tables count them) as an integer or a float.
  int32_t integer(int n) const {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      const uint32_t b = bytes_[size_t(4 * (n - 1) + (big_ ? i : 3 - i))];
      v = (v << 8) | b;
    }
    return int32_t(v);
  }
  double real(int n) const {
    const uint32_t v = uint32_t(integer(n));
    float f;
    std::memcpy(&f, &v, 4);
    return double(f);
  }

 private:
  const std::vector<uint8_t>& bytes_;
  bool big_;
};

bool knownMode(int32_t mode) {
  return mode == 0 || mode == 1 || mode == 2 || mode == 3 || mode == 4 || mode == 6 || mode == 12 ||
         mode == 101;
}

// The data's byte order: the machine stamp's (0x44 little-endian, 0x11 big-endian), else, for
// old files without one, the order in which the mode is one the format has.
bool bigEndianData(const std::vector<uint8_t>& h) {
  if (h[212] == 0x44) return false;
  if (h[212] == 0x11) return true;
  return !knownMode(MrcHeader(h, false).integer(4)) && knownMode(MrcHeader(h, true).integer(4));
}

// Unit vectors of the crystal axes a, b, c in Cartesian space (the PDB's orthogonalization: a
// along x, b in the xy plane) from the cell angles CELLB (alpha between b and c, beta between a
// and c, gamma between a and b, degrees). Angles all 0 (no cell) or all 90 give the identity;
// angles that make no cell give it too, with a note.
glm::dmat3 cellBasis(const MrcHeader& h, std::vector<std::string>& notes) {
  const glm::dvec3 deg(h.real(14), h.real(15), h.real(16));
  if (deg == glm::dvec3(0.0) || deg == glm::dvec3(90.0)) return glm::dmat3(1.0);
  const glm::dvec3 rad = deg * (3.14159265358979323846 / 180.0);
  const glm::dvec3 c(std::cos(rad.x), std::cos(rad.y), std::cos(rad.z));
  const double sinGamma = std::sin(rad.z);
  const double cy = (c.x - c.y * c.z) / sinGamma;
  const double cz2 = 1.0 - c.y * c.y - cy * cy;
  bool valid = cz2 > 1e-6;
  for (int a = 0; a < 3; ++a) valid = valid && std::isfinite(deg[a]) && deg[a] > 0 && deg[a] < 180;
  if (!valid) {
    notes.push_back("cell angles " + std::to_string(deg.x) + ", " + std::to_string(deg.y) + ", " +
                    std::to_string(deg.z) + " make no cell: axes taken as orthogonal");
    return glm::dmat3(1.0);
  }
  return glm::dmat3(glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(c.z, sinGamma, 0.0),
                    glm::dvec3(c.y, cy, std::sqrt(cz2)));
}

}  // namespace

Volume loadMrc(const std::string& path) {
  const uint64_t size = regularFileSize(path);
  if (size < kHeaderBytes)
    failLoad(path, "not an MRC file: " + std::to_string(size) +
                       " bytes, shorter than its 1024-byte header");
  const std::vector<uint8_t> bytes = readFileRange(path, 0, kHeaderBytes, "MRC header");
  const bool big = bigEndianData(bytes);
  const MrcHeader h(bytes, big);
  VolumeLayout layout;
  layout.bigEndian = big;
  layout.dims = {h.integer(1), h.integer(2), h.integer(3)};
  const int32_t mode = h.integer(4);
  bool half = false;
  switch (mode) {
    case 0:  // signed bytes (MRC2014), unless IMOD wrote them and says they are not
      layout.type = h.integer(39) == kImodStamp && !(h.integer(40) & 1) ? FileScalar::UInt8
                                                                        : FileScalar::Int8;
      break;
    case 1:
      layout.type = FileScalar::Int16;
      break;
    case 2:
      layout.type = FileScalar::Float32;
      break;
    case 6:
      layout.type = FileScalar::UInt16;
      break;
    case 12:
      layout.type = FileScalar::Float32;  // read as half floats below
      half = true;
      break;
    default:
      failLoad(path, "MRC mode " + std::to_string(mode) +
                         " is not read (0, 1, 2, 6 or 12: integers and real numbers; not complex "
                         "or 4-bit data)");
  }
  // Axis order: MAPC, MAPR, MAPS name the world axis of the columns, rows and sections.
  // (Words as read, in 64 bits: a hostile INT_MIN minus one must not overflow.)
  int64_t axis[3] = {int64_t(h.integer(17)) - 1, int64_t(h.integer(18)) - 1,
                     int64_t(h.integer(19)) - 1};
  if (axis[0] == -1 && axis[1] == -1 && axis[2] == -1) axis[0] = 0, axis[1] = 1, axis[2] = 2;
  bool seen[3] = {false, false, false};
  for (const int64_t a : axis) {
    if (a < 0 || a > 2 || seen[a])
      failLoad(path, "bad axis order MAPC, MAPR, MAPS " + std::to_string(axis[0] + 1) + ", " +
                         std::to_string(axis[1] + 1) + ", " + std::to_string(axis[2] + 1) +
                         " (a permutation of 1, 2, 3)");
    seen[a] = true;
  }
  // Spacing along each world axis: the cell's length over its samples (angstroms).
  glm::dvec3 world(1.0);
  bool sized = true;
  for (int a = 0; a < 3; ++a) {
    const double cell = h.real(11 + a);
    const int32_t samples = h.integer(8 + a);
    if (samples > 0 && cell > 0.0 && std::isfinite(cell / samples))
      world[a] = cell / samples;
    else
      sized = false;
  }
  if (!sized) layout.notes.push_back("no cell size for some axes: spacing 1 assumed there");
  const glm::dmat3 basis = cellBasis(h, layout.notes);
  const glm::dvec3 origin(h.real(50), h.real(51), h.real(52));
  const bool placed = origin != glm::dvec3(0.0) && std::isfinite(origin.x) &&
                      std::isfinite(origin.y) && std::isfinite(origin.z);
  // A skewed cell's grid is resampled onto an upright one by makeVolume, as a tilted gantry's.
  layout.origin = placed ? origin : glm::dvec3(0.0);
  for (int i = 0; i < 3; ++i) {
    layout.spacing[i] = world[axis[i]];
    layout.direction[i] = basis[int(axis[i])];
    // Without ORIGIN, the first voxel lies NXSTART, NYSTART, NZSTART samples along its axes.
    if (!placed) layout.origin += double(h.integer(5 + i)) * world[axis[i]] * basis[int(axis[i])];
  }
  if (axis[0] != 0 || axis[1] != 1 || axis[2] != 2)
    layout.notes.push_back("axis order MAPC, MAPR, MAPS " + std::to_string(axis[0] + 1) + ", " +
                           std::to_string(axis[1] + 1) + ", " + std::to_string(axis[2] + 1));
  layout.unit = "\xC3\x85";  // angstroms

  const int32_t extended = h.integer(24);  // NSYMBT: extended header bytes
  if (extended < 0 || uint64_t(extended) > size - kHeaderBytes)
    failLoad(path, "bad extended header length " + std::to_string(extended) + " (the file has " +
                       std::to_string(size) + " bytes)");
  const uint64_t offset = kHeaderBytes + uint64_t(extended);
  const FileScalar stored = half ? FileScalar::Int16 : layout.type;  // 2 bytes a half float
  const uint64_t need = dataByteCount(path, layout.dims, stored);
  std::vector<uint8_t> data = readFileRange(path, offset, need);  // checks the file holds it
  if (half) {
    dataByteCount(path, layout.dims, FileScalar::Float32);  // the floats fit in memory too
    std::vector<uint8_t> floats(size_t(need) * 2);
    for (size_t i = 0; i < size_t(need / 2); ++i) {
      const uint16_t v = big ? uint16_t(data[2 * i] << 8 | data[2 * i + 1])
                             : uint16_t(data[2 * i + 1] << 8 | data[2 * i]);
      const float f = glm::unpackHalf1x16(v);
      std::memcpy(&floats[4 * i], &f, 4);
    }
    data = std::move(floats);
    layout.bigEndian = hostIsBigEndian();
    layout.notes.push_back("half floats (MRC mode 12) read as float32");
  }
  return makeVolume(path, layout, std::move(data));
}

}  // namespace ewa
