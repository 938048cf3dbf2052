// Writing a volume as a single-file NIfTI-1, or NIfTI-2 where it must (.nii, .nii.gz):
// --save-volume.
#include "io/nifti_writer.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/volume_orientation.h"
#include "io/byte_order.h"
#include "io/nifti_header.h"

namespace ewa {

namespace {

// Little-endian fields at their offsets, whatever the host's byte order.
class HeaderBytes {
 public:
  explicit HeaderBytes(size_t size) : bytes_(size + 4, 0) {}  // + the extension flag: none
  void i16(size_t at, int v) { put(at, uint16_t(int16_t(v)), 2); }
  void i32(size_t at, int32_t v) { put(at, uint32_t(v), 4); }
  void i64(size_t at, int64_t v) { put(at, uint64_t(v), 8); }
  void f32(size_t at, double v) {
    const auto f = float(v);
    uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    put(at, bits, 4);
  }
  void f64(size_t at, double v) {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, 8);
    put(at, bits, 8);
  }
  void u8(size_t at, int v) { bytes_[at] = uint8_t(v); }
  void text(size_t at, const char* s, size_t n) { std::memcpy(&bytes_[at], s, n); }
  void text(size_t at, const char* s) { text(at, s, std::strlen(s)); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  void put(size_t at, uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_[at + size_t(i)] = uint8_t(v >> (8 * i));
  }
  std::vector<uint8_t> bytes_;
};

// What either header version holds of a volume.
struct NiftiFields {
  int64_t dim[3] = {};
  int datatype = 0, bitpix = 0, unit = 0;
  double pixdim[4] = {1.0, 1.0, 1.0, 1.0};  // qfac, then the spacing
  int qformCode = 0, sformCode = 0;
  double quatern[3] = {}, qoffset[3] = {}, srow[3][4] = {};
};

std::vector<uint8_t> nifti1Header(const NiftiFields& f) {
  HeaderBytes h(kNifti1Size);
  h.i32(0, int32_t(kNifti1Size));
  h.text(38, "r");  // regular
  h.i16(40, 3);
  for (int a = 0; a < 7; ++a) h.i16(42 + 2 * size_t(a), a < 3 ? int(f.dim[a]) : 1);
  h.i16(70, f.datatype);
  h.i16(72, f.bitpix);
  for (int a = 0; a < 4; ++a) h.f32(76 + 4 * size_t(a), f.pixdim[a]);
  h.f32(108, double(kNifti1Size + 4));  // vox_offset
  h.u8(123, f.unit);                    // xyzt_units: no time unit
  h.text(148, "ewaview");               // descrip
  h.i16(252, f.qformCode);
  h.i16(254, f.sformCode);
  for (int i = 0; i < 3; ++i) h.f32(256 + 4 * size_t(i), f.quatern[i]);
  for (int i = 0; i < 3; ++i) h.f32(268 + 4 * size_t(i), f.qoffset[i]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) h.f32(280 + 16 * size_t(r) + 4 * size_t(c), f.srow[r][c]);
  h.text(344, "n+1");  // magic, its NUL already there
  return h.bytes();
}

// NIfTI-2: the same fields, 64-bit, at the offsets of its 540-byte header.
std::vector<uint8_t> nifti2Header(const NiftiFields& f) {
  HeaderBytes h(kNifti2Size);
  h.i32(0, int32_t(kNifti2Size));
  h.text(4, "n+2\0\r\n\032\n", 8);  // magic
  h.i16(12, f.datatype);
  h.i16(14, f.bitpix);
  h.i64(16, 3);
  for (int a = 0; a < 7; ++a) h.i64(24 + 8 * size_t(a), a < 3 ? f.dim[a] : 1);
  for (int a = 0; a < 4; ++a) h.f64(104 + 8 * size_t(a), f.pixdim[a]);
  h.i64(168, int64_t(kNifti2Size + 4));  // vox_offset
  h.text(240, "ewaview");                // descrip
  h.i32(344, f.qformCode);
  h.i32(348, f.sformCode);
  for (int i = 0; i < 3; ++i) h.f64(352 + 8 * size_t(i), f.quatern[i]);
  for (int i = 0; i < 3; ++i) h.f64(376 + 8 * size_t(i), f.qoffset[i]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) h.f64(400 + 32 * size_t(r) + 8 * size_t(c), f.srow[r][c]);
  h.i32(500, f.unit);  // xyzt_units
  return h.bytes();
}

// NIfTI's datatype code and bits per voxel of each type the viewer keeps.
void niftiType(ScalarType type, int* code, int* bits) {
  switch (type) {
    case ScalarType::UInt8:
      *code = 2, *bits = 8;
      return;
    case ScalarType::Int16:
      *code = 4, *bits = 16;
      return;
    case ScalarType::UInt16:
      *code = 512, *bits = 16;
      return;
    case ScalarType::Float32:
      *code = 16, *bits = 32;
      return;
  }
}

// xyzt_units' spatial code: 1 metre, 2 millimetre, 3 micron; 0 for a unit NIfTI cannot name.
int niftiUnit(const std::string& unit) {
  if (unit == "m") return 1;
  if (unit == "mm") return 2;
  if (unit == "\xC2\xB5m") return 3;
  return 0;
}

// The quaternion (b, c, d) and qfac of the rotation in `r` (columns orthonormal), as NIfTI-1
// defines them: a proper rotation after the third column is negated when the determinant is
// negative (qfac -1), a >= 0.
void toQuaternion(glm::dmat3 r, double q[3], double* qfac) {
  *qfac = glm::determinant(r) < 0.0 ? -1.0 : 1.0;
  r[2] *= *qfac;
  // r[col][row]: R(i,j) of the standard's formula is r[j-1][i-1].
  const auto R = [&](int i, int j) { return r[j - 1][i - 1]; };
  double a = R(1, 1) + R(2, 2) + R(3, 3) + 1.0, b = 0, c = 0, d = 0;
  if (a > 0.5) {
    a = 0.5 * std::sqrt(a);
    b = 0.25 * (R(3, 2) - R(2, 3)) / a;
    c = 0.25 * (R(1, 3) - R(3, 1)) / a;
    d = 0.25 * (R(2, 1) - R(1, 2)) / a;
  } else {
    const double xd = 1.0 + R(1, 1) - (R(2, 2) + R(3, 3));
    const double yd = 1.0 + R(2, 2) - (R(1, 1) + R(3, 3));
    const double zd = 1.0 + R(3, 3) - (R(1, 1) + R(2, 2));
    if (xd > 1.0) {
      b = 0.5 * std::sqrt(xd);
      c = 0.25 * (R(1, 2) + R(2, 1)) / b;
      d = 0.25 * (R(1, 3) + R(3, 1)) / b;
      a = 0.25 * (R(3, 2) - R(2, 3)) / b;
    } else if (yd > 1.0) {
      c = 0.5 * std::sqrt(yd);
      b = 0.25 * (R(1, 2) + R(2, 1)) / c;
      d = 0.25 * (R(2, 3) + R(3, 2)) / c;
      a = 0.25 * (R(1, 3) - R(3, 1)) / c;
    } else {
      d = 0.5 * std::sqrt(zd);
      b = 0.25 * (R(1, 3) + R(3, 1)) / d;
      c = 0.25 * (R(2, 3) + R(3, 2)) / d;
      a = 0.25 * (R(2, 1) - R(1, 2)) / d;
    }
    if (a < 0.0) b = -b, c = -c, d = -d;
  }
  q[0] = b, q[1] = c, q[2] = d;
}

}  // namespace

bool needsNifti2(const Volume& volume) {
  for (int a = 0; a < 3; ++a) {
    const double spacing = volume.spacing()[a], origin = volume.origin()[a];
    if (volume.dims()[size_t(a)] > 32767 || !(spacing >= FLT_MIN && spacing <= FLT_MAX) ||
        !(std::abs(origin) <= FLT_MAX))
      return true;
  }
  return false;
}

std::string encodeNifti(const Volume& volume) {
  const auto& d = volume.dims();
  const glm::dmat3 direction = volume.direction();
  const glm::dvec3 spacing = volume.spacing(), origin = volume.origin();
  NiftiFields f;
  for (int a = 0; a < 3; ++a) f.dim[a] = d[size_t(a)], f.pixdim[a + 1] = spacing[a];
  niftiType(volume.type(), &f.datatype, &f.bitpix);
  f.unit = niftiUnit(volume.unit());
  if (volume.patientFrame() || origin != glm::dvec3(0.0) || direction != glm::dmat3(1.0)) {
    // NIfTI's world is RAS: the viewer's LPS with x and y negated.
    const glm::dvec3 toRas(-1.0, -1.0, 1.0);
    for (int row = 0; row < 3; ++row) {
      for (int a = 0; a < 3; ++a) f.srow[row][a] = toRas[row] * direction[a][row] * spacing[a];
      f.srow[row][3] = toRas[row] * origin[row];
    }
    f.sformCode = 1;  // scanner
    glm::dmat3 rotation;
    for (int a = 0; a < 3; ++a) rotation[a] = toRas * direction[a];
    if (isOrthonormal(rotation, 1e-6)) {
      toQuaternion(rotation, f.quatern, &f.pixdim[0]);
      for (int i = 0; i < 3; ++i) f.qoffset[i] = toRas[i] * origin[i];
      f.qformCode = 1;
    }
  }
  const std::vector<uint8_t> header = needsNifti2(volume) ? nifti2Header(f) : nifti1Header(f);
  std::string out(header.begin(), header.end());
  std::vector<uint8_t> voxels = volume.bytes();
  if (hostIsBigEndian()) swapBytes(voxels.data(), voxels.size(), scalarSize(volume.type()));
  out.append(reinterpret_cast<const char*>(voxels.data()), voxels.size());
  return out;
}

}  // namespace ewa
