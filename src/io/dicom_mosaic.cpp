// Siemens mosaics: the CSA header's NumberOfImagesInMosaic, the tiles' geometry and planes.
#include "io/dicom_mosaic.h"

#include <gdcmReader.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "io/dicom_csa.h"
#include "io/load_failure.h"
#include "io/text_fields.h"

namespace ewa {

namespace {

const gdcm::Tag kPixelData(0x7fe0, 0x0010);

// The bytes of element `tag` of `ds`; empty when absent or not bytes.
std::string elementBytes(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
  if (!ds.FindDataElement(tag)) return {};
  const gdcm::ByteValue* value = ds.GetDataElement(tag).GetByteValue();
  return value ? std::string(value->GetPointer(), value->GetLength()) : std::string();
}

// The CSA image header: (0029,xx10) of the private block its creator names "SIEMENS CSA HEADER".
std::string csaImageHeader(const gdcm::DataSet& ds) {
  for (uint16_t block = 0x10; block <= 0xff; ++block) {
    const std::string creator = trim(elementBytes(ds, gdcm::Tag(0x0029, block)).c_str());
    if (creator == "SIEMENS CSA HEADER")
      return elementBytes(ds, gdcm::Tag(0x0029, uint16_t(block << 8 | 0x10)));
  }
  return {};
}

}  // namespace

std::optional<DicomMosaic> dicomMosaic(const DicomSlice& file) {
  if (!file.mosaic || file.frames != 1) return std::nullopt;
  gdcm::Reader reader;
  reader.SetFileName(file.file.c_str());
  if (!reader.ReadUpToTag(kPixelData)) failLoad(file.file, "GDCM cannot read the header");
  const std::string csa = csaImageHeader(reader.GetFile().GetDataSet());
  const auto* bytes = reinterpret_cast<const uint8_t*>(csa.data());
  const std::vector<std::string> count = csaValues(bytes, csa.size(), "NumberOfImagesInMosaic");
  int64_t n = 0;
  if (count.empty() || !parseInt64(count.front(), n) || n < 2) return std::nullopt;
  DicomMosaic m;
  m.count = n;
  // Rows and Columns are 16-bit: a count past their product is refused before it is squared.
  m.perRow = n > file.columns * file.rows ? 0 : int64_t(std::ceil(std::sqrt(double(n))));
  while (m.perRow > 0 && m.perRow * m.perRow < n) ++m.perRow;  // rounding of the square root
  if (m.perRow == 0 || m.perRow > file.columns || m.perRow > file.rows ||
      file.columns % m.perRow != 0 || file.rows % m.perRow != 0)
    failLoad(file.file, "a Siemens mosaic of " + std::to_string(n) + " images" +
                            (m.perRow > 0 ? " (" + std::to_string(m.perRow) + " x " +
                                                std::to_string(m.perRow) + " tiles)"
                                          : std::string()) +
                            " that its " + std::to_string(file.columns) + " x " +
                            std::to_string(file.rows) + " pixels do not hold");
  m.tileColumns = file.columns / m.perRow;
  m.tileRows = file.rows / m.perRow;
  const glm::dvec3 row(file.orientation[0], file.orientation[1], file.orientation[2]);
  const glm::dvec3 column(file.orientation[3], file.orientation[4], file.orientation[5]);
  m.first = file.position + row * file.columnSpacing * double(file.columns - m.tileColumns) / 2.0 +
            column * file.rowSpacing * double(file.rows - m.tileRows) / 2.0;
  m.spacing = file.spacingBetweenSlices > 0.0 ? file.spacingBetweenSlices : file.sliceThickness;
  if (!(m.spacing > 0.0)) m.spacing = 1.0, m.spacingAssumed = true;
  std::vector<double> normal;
  for (const std::string& v : csaValues(bytes, csa.size(), "SliceNormalVector")) {
    double x = 0.0;
    if (parseDouble(v, x) && std::isfinite(x)) normal.push_back(x);
  }
  if (normal.size() == 3)
    m.reversed = glm::dot(glm::dvec3(normal[0], normal[1], normal[2]),
                          dicomSliceNormal(file.orientation)) < 0.0;
  return m;
}

DicomSlice selectMosaicVolume(const std::string& path, std::vector<DicomSlice> files, int volume,
                              std::vector<std::string>& notes, int* count) {
  std::stable_sort(files.begin(), files.end(), [](const DicomSlice& a, const DicomSlice& b) {
    return a.instance != b.instance ? a.instance < b.instance : a.file < b.file;
  });
  checkFrame(path, volume, int64_t(files.size()), "the series has", "mosaic",
             " (volumes: time points or directions)");
  if (files.size() > 1)
    notes.push_back("a series of " + std::to_string(files.size()) +
                    " mosaics, one volume each in InstanceNumber order: showing volume " +
                    std::to_string(volume) + " (--frame N picks another)");
  if (count) *count = int(std::min<size_t>(files.size(), 1 << 30));
  return files[size_t(volume)];
}

std::vector<double> mosaicPlanes(const std::vector<double>& values, int64_t columns,
                                 const DicomMosaic& m) {
  const size_t plane = size_t(m.tileColumns) * size_t(m.tileRows);
  std::vector<double> out(plane * size_t(m.count));
  for (int64_t k = 0; k < m.count; ++k) {
    const int64_t x0 = (k % m.perRow) * m.tileColumns, y0 = (k / m.perRow) * m.tileRows;
    const int64_t z = m.reversed ? m.count - 1 - k : k;
    for (int64_t j = 0; j < m.tileRows; ++j)
      std::copy_n(values.begin() + ptrdiff_t((y0 + j) * columns + x0), m.tileColumns,
                  out.begin() + ptrdiff_t(size_t(z) * plane + size_t(j * m.tileColumns)));
  }
  return out;
}

}  // namespace ewa
