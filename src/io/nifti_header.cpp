// NIfTI headers: fixed offsets read in the file's byte order, and sform/qform to LPS.
#include "io/nifti_header.h"

#include <cmath>
#include <cstring>

#include "io/byte_order.h"
#include "io/length_unit.h"
#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

// Reads header fields at fixed offsets in the file's byte order.
class FieldReader {
 public:
  FieldReader(const std::vector<uint8_t>& bytes, bool bigEndian)
      : bytes_(bytes), bigEndian_(bigEndian) {}
  int64_t i16(size_t at) const { return int16_t(readUnsigned(&bytes_[at], 2, bigEndian_)); }
  int64_t i32(size_t at) const { return int32_t(readUnsigned(&bytes_[at], 4, bigEndian_)); }
  int64_t i64(size_t at) const { return int64_t(readUnsigned(&bytes_[at], 8, bigEndian_)); }
  double f32(size_t at) const {
    const auto u = uint32_t(readUnsigned(&bytes_[at], 4, bigEndian_));
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
  double f64(size_t at) const {
    const uint64_t u = readUnsigned(&bytes_[at], 8, bigEndian_);
    double d;
    std::memcpy(&d, &u, 8);
    return d;
  }

 private:
  const std::vector<uint8_t>& bytes_;
  bool bigEndian_;
};

}  // namespace

NiftiHeader parseNiftiHeader(const std::string& path, const std::vector<uint8_t>& bytes) {
  if (bytes.size() < 4) failLoad(path, "file is too short for a NIfTI header");
  NiftiHeader h;
  const uint64_t le = readUnsigned(bytes.data(), 4, false);
  const uint64_t be = readUnsigned(bytes.data(), 4, true);
  if (le == kNifti1Size || be == kNifti1Size) {
    h.bigEndian = le != kNifti1Size;
  } else if (le == kNifti2Size || be == kNifti2Size) {
    h.nifti2 = true;
    h.bigEndian = le != kNifti2Size;
  } else {
    failLoad(path, "not a NIfTI file (header size is neither 348 nor 540)");
  }
  const size_t need = h.nifti2 ? kNifti2Size : kNifti1Size;
  if (bytes.size() < need)
    failLoad(path, "NIfTI header is truncated (" + std::to_string(bytes.size()) + " of " +
                       std::to_string(need) + " bytes)");
  const FieldReader r(bytes, h.bigEndian);
  if (!h.nifti2) {
    const std::string magic(reinterpret_cast<const char*>(&bytes[344]), 3);
    const std::string name = toLower(path);
    const bool hdr =
        name.size() > 4 && (name.compare(name.size() - 4, 4, ".hdr") == 0 ||
                            (name.size() > 7 && name.compare(name.size() - 7, 7, ".hdr.gz") == 0));
    h.analyze = magic != "n+1" && magic != "ni1" && hdr;
    if (magic != "n+1" && magic != "ni1" && !h.analyze)
      failLoad(path, "bad NIfTI-1 magic " + quoteText(magic));
    for (int i = 0; i < 8; ++i) h.dim[i] = r.i16(40 + 2 * i);
    for (int i = 0; i < 8; ++i) h.pixdim[i] = r.f32(76 + 4 * i);
    h.datatype = int(r.i16(70));
    h.voxOffset = r.f32(108);
    h.sclSlope = r.f32(112);
    h.sclInter = r.f32(116);
    h.xyztUnits = bytes[123];
    h.qformCode = int(r.i16(252));
    h.sformCode = int(r.i16(254));
    for (int i = 0; i < 3; ++i) h.quatern[i] = r.f32(256 + 4 * i);
    for (int i = 0; i < 3; ++i) h.qoffset[i] = r.f32(268 + 4 * i);
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 4; ++c) h.srow[row][c] = r.f32(280 + 16 * row + 4 * c);
    if (h.analyze) {
      h.qformCode = h.sformCode = 0;  // those bytes are Analyze's orient and originator
      h.sclSlope = h.sclInter = 0.0;
      h.analyzeUnit.assign(reinterpret_cast<const char*>(&bytes[56]), 4);  // vox_units
      h.analyzeUnit = h.analyzeUnit.substr(0, h.analyzeUnit.find('\0'));
    }
  } else {
    const std::string magic(reinterpret_cast<const char*>(&bytes[4]), 3);
    if (magic != "n+2" && magic != "ni2") failLoad(path, "bad NIfTI-2 magic " + quoteText(magic));
    for (int i = 0; i < 8; ++i) h.dim[i] = r.i64(16 + 8 * i);
    for (int i = 0; i < 8; ++i) h.pixdim[i] = r.f64(104 + 8 * i);
    h.datatype = int(r.i16(12));
    h.voxOffset = double(r.i64(168));
    h.sclSlope = r.f64(176);
    h.sclInter = r.f64(184);
    h.xyztUnits = int(r.i32(500));
    h.qformCode = int(r.i32(344));
    h.sformCode = int(r.i32(348));
    for (int i = 0; i < 3; ++i) h.quatern[i] = r.f64(352 + 8 * i);
    for (int i = 0; i < 3; ++i) h.qoffset[i] = r.f64(376 + 8 * i);
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 4; ++c) h.srow[row][c] = r.f64(400 + 32 * row + 8 * c);
  }
  return h;
}

// NIfTI's world is RAS; the viewer's is LPS: x and y change sign.
void placeNiftiInWorld(const NiftiHeader& h, VolumeLayout& layout) {
  const int spaceUnit = h.xyztUnits & 7;  // 1 metre, 2 millimetre, 3 micron
  layout.unit = lengthUnitName(h.analyze        ? h.analyzeUnit
                               : spaceUnit == 1 ? "m"
                               : spaceUnit == 2 ? "mm"
                               : spaceUnit == 3 ? "micron"
                                                : "");
  if (h.analyze) {
    for (int a = 0; a < 3; ++a) layout.spacing[a] = h.pixdim[a + 1];
    layout.notes.push_back(
        "Analyze 7.5 header (no NIfTI magic): spacing from pixdim, no orientation or scaling");
    return;
  }
  const glm::dvec3 toLps(-1.0, -1.0, 1.0);
  if (h.sformCode > 0) {
    for (int a = 0; a < 3; ++a) {
      const glm::dvec3 column(h.srow[0][a], h.srow[1][a], h.srow[2][a]);
      const double length =
          std::hypot(column.x, column.y, column.z);  // no overflow or underflow on the way
      layout.spacing[a] = length;
      layout.direction[a] = length > 0.0 ? toLps * column / length : glm::dvec3(0.0);
    }
    layout.origin = toLps * glm::dvec3(h.srow[0][3], h.srow[1][3], h.srow[2][3]);
    layout.patientFrame = true;
    return;
  }
  for (int a = 0; a < 3; ++a) layout.spacing[a] = h.pixdim[a + 1];
  if (h.qformCode <= 0) return;  // "method 1": no world frame
  const double b = h.quatern[0], c = h.quatern[1], d = h.quatern[2];
  const double a2 = 1.0 - (b * b + c * c + d * d);
  const double a = a2 > 0.0 ? std::sqrt(a2) : 0.0;
  const double qfac = h.pixdim[0] < 0.0 ? -1.0 : 1.0;
  const double m[3][3] = {
      {a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
      {2 * (b * c + a * d), a * a + c * c - b * b - d * d, 2 * (c * d - a * b)},
      {2 * (b * d - a * c), 2 * (c * d + a * b), a * a + d * d - c * c - b * b}};
  for (int col = 0; col < 3; ++col) {
    const double sign = col == 2 ? qfac : 1.0;
    layout.direction[col] = toLps * glm::dvec3(m[0][col], m[1][col], m[2][col]) * sign;
  }
  layout.origin = toLps * glm::dvec3(h.qoffset[0], h.qoffset[1], h.qoffset[2]);
  layout.patientFrame = true;
}

}  // namespace ewa
