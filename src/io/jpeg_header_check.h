// A JPEG stream's header (SOI to the first SOS) walked before GDCM's JPEG codec reads it: the
// codec asserts (aborts) on headers libjpeg only warns about or that it did not plan for.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ewa {

// What is wrong with the header of the JPEG stream (ISO 10918: baseline, extended, progressive
// or lossless) that starts at `data`, or "" when GDCM's codec can be given it. Bytes that do not
// start with an SOI marker are not a stream's start (a later fragment of one) and pass.
// Refused, each found to abort or crash GDCM 3.0 (Debian 12): stray bytes between markers, a
// header cut short, a JFIF version other than 1, marker segments of impossible lengths, frames
// other than baseline, extended, progressive and lossless, any but 1 or 3 components, an Adobe
// colour transform it does not know, and precisions its codecs do not decode (8, 12 or 16 bits
// lossy; 8 to 16 lossless).
std::string jpegHeaderProblem(const uint8_t* data, size_t size);

// Whether a DICOM transfer syntax UID is one of the JPEG (ISO 10918) ones GDCM decodes with
// that codec (not JPEG-LS or JPEG 2000).
bool isJpegTransferSyntax(const std::string& uid);

}  // namespace ewa
