// Writing a volume as a single-file NIfTI-1 (.nii, or .nii.gz gzip-compressed): --save-volume.
#include "io/nifti_writer.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/volume_orientation.h"
#include "io/byte_order.h"
#include "io/nifti_header.h"

namespace ewa {

namespace {

// Little-endian fields at their NIfTI-1 offsets, whatever the host's byte order.
class HeaderBytes {
 public:
  HeaderBytes() : bytes_(kNifti1Size + 4, 0) {}  // + the extension flag: none
  void i16(size_t at, int v) { put(at, uint32_t(uint16_t(int16_t(v))), 2); }
  void i32(size_t at, int32_t v) { put(at, uint32_t(v), 4); }
  void f32(size_t at, double v) {
    const auto f = float(v);
    uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    put(at, bits, 4);
  }
  void u8(size_t at, int v) { bytes_[at] = uint8_t(v); }
  void text(size_t at, const char* s) { std::memcpy(&bytes_[at], s, std::strlen(s)); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  void put(size_t at, uint32_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_[at + size_t(i)] = uint8_t(v >> (8 * i));
  }
  std::vector<uint8_t> bytes_;
};

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

std::string encodeNifti(const Volume& volume, const std::string& name) {
  const auto& d = volume.dims();
  for (int a = 0; a < 3; ++a)
    if (d[size_t(a)] > 32767)
      throw std::runtime_error(name + ": an axis of " + std::to_string(d[size_t(a)]) +
                               " voxels is more than NIfTI-1 holds (32767); save it as .nrrd");
  const glm::dmat3 direction = volume.direction();
  const glm::dvec3 spacing = volume.spacing(), origin = volume.origin();
  // NIfTI-1 keeps the placement in float32: a spacing it would round to 0 or infinity, or an
  // origin beyond its range, cannot be written.
  for (int a = 0; a < 3; ++a)
    if (!(spacing[a] >= FLT_MIN && spacing[a] <= FLT_MAX) || !(std::abs(origin[a]) <= FLT_MAX))
      throw std::runtime_error(name + ": the volume's spacing or origin is outside NIfTI-1's " +
                               "float32 range; save it as .nrrd");

  int code = 0, bits = 0;
  niftiType(volume.type(), &code, &bits);
  HeaderBytes h;
  h.i32(0, int32_t(kNifti1Size));
  h.text(38, "r");  // regular
  h.i16(40, 3);
  for (int a = 0; a < 7; ++a) h.i16(42 + 2 * size_t(a), a < 3 ? int(d[size_t(a)]) : 1);
  h.i16(70, code);
  h.i16(72, bits);
  h.f32(108, double(kNifti1Size + 4));  // vox_offset
  h.u8(123, niftiUnit(volume.unit()));  // xyzt_units: no time unit
  h.text(148, "ewaview");               // descrip
  h.text(344, "n+1");                   // magic, its NUL already there

  double qfac = 1.0;
  if (volume.patientFrame() || origin != glm::dvec3(0.0) || direction != glm::dmat3(1.0)) {
    // NIfTI's world is RAS: the viewer's LPS with x and y negated.
    const glm::dvec3 toRas(-1.0, -1.0, 1.0);
    for (int row = 0; row < 3; ++row) {
      const size_t at = 280 + 16 * size_t(row);  // srow_x, srow_y, srow_z
      for (int a = 0; a < 3; ++a)
        h.f32(at + 4 * size_t(a), toRas[row] * direction[a][row] * spacing[a]);
      h.f32(at + 12, toRas[row] * origin[row]);
    }
    h.i16(254, 1);  // sform_code: scanner
    glm::dmat3 rotation;
    for (int a = 0; a < 3; ++a) rotation[a] = toRas * direction[a];
    if (isOrthonormal(rotation, 1e-6)) {
      double q[3];
      toQuaternion(rotation, q, &qfac);
      for (int i = 0; i < 3; ++i) h.f32(256 + 4 * size_t(i), q[i]);
      for (int i = 0; i < 3; ++i) h.f32(268 + 4 * size_t(i), toRas[i] * origin[i]);
      h.i16(252, 1);  // qform_code: scanner
    }
  }
  h.f32(76, qfac);  // pixdim[0]
  for (int a = 0; a < 3; ++a) h.f32(80 + 4 * size_t(a), spacing[a]);

  const std::vector<uint8_t>& header = h.bytes();
  std::string out(header.begin(), header.end());
  std::vector<uint8_t> voxels = volume.bytes();
  if (hostIsBigEndian()) swapBytes(voxels.data(), voxels.size(), scalarSize(volume.type()));
  out.append(reinterpret_cast<const char*>(voxels.data()), voxels.size());
  return out;
}

}  // namespace ewa
