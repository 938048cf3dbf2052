// DICOM colour spaces: which are read where, Y'CbCr to RGB, and uncompressed 4:2:2 chroma.
#include "io/dicom_colour.h"

#include <algorithm>
#include <cmath>

#include "io/jpeg_header_check.h"
#include "io/load_failure.h"

namespace ewa {

bool isYbrFull(const std::string& pi) {
  return pi == "YBR_FULL" || pi == "YBR_FULL_422";
}

bool isColourSpace(const std::string& pi) {
  return pi == "RGB" || isYbrFull(pi) || pi == "YBR_RCT" || pi == "YBR_ICT";
}

std::string colourCodingProblem(const std::string& pi, const std::string& syntax,
                                bool encapsulated) {
  const bool ok = pi == "YBR_FULL_422" ? !encapsulated || isJpegTransferSyntax(syntax)
                  : pi == "YBR_RCT" || pi == "YBR_ICT" ? isJpeg2000TransferSyntax(syntax)
                                                       : true;
  if (ok) return "";
  return "PhotometricInterpretation " + quoteText(pi, 20) +
         (encapsulated ? " in transfer syntax " + quoteText(syntax, 40)
                       : std::string(" uncompressed")) +
         " is not read (" + (pi == "YBR_FULL_422" ? "JPEG or uncompressed" : "JPEG 2000") +
         " only)";
}

void checkColourCoding(const DicomSlice& s, gdcm::TransferSyntax ts) {
  const char* uid = gdcm::TransferSyntax::GetTSString(ts);
  const std::string problem =
      colourCodingProblem(s.photometric, uid ? uid : "", ts.IsEncapsulated());
  if (!problem.empty()) failLoad(s.file, problem);
}

double rgbOfYbr(double y, double cb, double cr, int component, int64_t bits) {
  const double half = std::ldexp(1.0, int(bits) - 1);
  cb -= half;
  cr -= half;
  const double v = component == 0   ? y + 1.402 * cr
                   : component == 1 ? y - 0.344136 * cb - 0.714136 * cr
                                    : y + 1.772 * cb;
  return std::clamp(std::round(v), 0.0, 2.0 * half - 1.0);
}

std::vector<double> rgbOfYbr422(const std::string& file, const uint8_t* bytes, uint64_t length,
                                int64_t columns, uint64_t count, int component) {
  if (columns <= 0 || columns % 2 != 0)
    failLoad(file, "YBR_FULL_422 with " + std::to_string(columns) +
                       " columns (its pixels come in pairs: an even number)");
  if (count % 2 != 0 || length / 2 < count)  // two bytes a pixel
    failLoad(file, "pixel data cannot hold " + std::to_string(count) +
                       " YBR_FULL_422 pixels (truncated file?)");
  std::vector<double> out(static_cast<size_t>(count));
  for (size_t pair = 0; pair < size_t(count / 2); ++pair) {
    const uint8_t* p = bytes + 4 * pair;  // Y1 Y2 Cb Cr
    out[2 * pair] = rgbOfYbr(p[0], p[2], p[3], component, 8);
    out[2 * pair + 1] = rgbOfYbr(p[1], p[2], p[3], component, 8);
  }
  return out;
}

}  // namespace ewa
