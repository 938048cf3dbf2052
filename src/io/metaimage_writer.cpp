// Encoding a volume as a MetaImage file with its data inside (.mha, zlib): --save-volume.
#include "io/metaimage_writer.h"

#include <cmath>
#include <vector>

#include "io/byte_order.h"
#include "io/deflate_encode.h"
#include "io/text_numbers.h"

namespace ewa {

namespace {

const char* metaType(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return "MET_UCHAR";
    case ScalarType::Int16:
      return "MET_SHORT";
    case ScalarType::UInt16:
      return "MET_USHORT";
    case ScalarType::Float32:
      return "MET_FLOAT";
  }
  return "MET_UCHAR";
}

// The values to the last digit, separated by spaces.
std::string numbers(std::initializer_list<double> values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : " ") + roundTripText(v);
  return out;
}

// ITK's AnatomicalOrientation: for each axis the side of the patient it starts from, along the
// patient axis it runs nearest, in LPS: +x runs from the right (R), +y from the front (A), +z
// from below (I); the identity is "RAI". Each data axis takes its own patient axis (the
// assignment with the largest components): at 45 degrees between two, a first-largest choice
// would name one patient axis twice ("RPP"), which no reader takes as patient axes.
std::string anatomicalOrientation(const glm::dmat3& direction) {
  static const int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const int* best = kOrders[0];
  double bestSum = -1.0;
  for (const int* order : kOrders) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) sum += std::abs(direction[a][order[a]]);
    if (sum > bestSum) bestSum = sum, best = order;
  }
  std::string code;
  static const char kFrom[3][2] = {{'R', 'L'}, {'A', 'P'}, {'I', 'S'}};
  for (int a = 0; a < 3; ++a) code += kFrom[best[a]][direction[a][best[a]] < 0.0 ? 1 : 0];
  return code;
}

// The header's lines up to ElementType; the data's lines follow.
std::string headerLines(const Volume& volume, const std::string& compressed) {
  const glm::dmat3& d = volume.direction();
  const glm::dvec3& s = volume.spacing();
  const glm::dvec3& o = volume.origin();
  const auto& n = volume.dims();
  std::string h =
      "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n";
  h += compressed;
  h += "TransformMatrix = " +
       numbers({d[0].x, d[0].y, d[0].z, d[1].x, d[1].y, d[1].z, d[2].x, d[2].y, d[2].z}) + "\n";
  h += "Offset = " + numbers({o.x, o.y, o.z}) + "\n";
  h += "CenterOfRotation = 0 0 0\n";
  if (volume.patientFrame()) h += "AnatomicalOrientation = " + anatomicalOrientation(d) + "\n";
  h += "ElementSpacing = " + numbers({s.x, s.y, s.z}) + "\n";
  h += "DimSize = " + std::to_string(n[0]) + " " + std::to_string(n[1]) + " " +
       std::to_string(n[2]) + "\n";
  return h + "ElementType = " + metaType(volume.type()) + "\n";
}

}  // namespace

std::vector<uint8_t> metaImageData(const Volume& volume) {
  std::vector<uint8_t> bytes = volume.bytes();
  if (hostIsBigEndian()) swapBytes(bytes.data(), bytes.size(), scalarSize(volume.type()));
  return bytes;
}

std::string encodeMetaImage(const Volume& volume) {
  const std::vector<uint8_t> bytes = metaImageData(volume);
  const std::string data = zlibBytes(bytes.data(), bytes.size());
  return headerLines(volume, "CompressedData = True\nCompressedDataSize = " +
                                 std::to_string(data.size()) + "\n") +
         "ElementDataFile = LOCAL\n" + data;
}

std::string encodeMetaImageHeader(const Volume& volume, const std::string& dataFile) {
  return headerLines(volume, "CompressedData = False\n") + "ElementDataFile = " + dataFile + "\n";
}

}  // namespace ewa
