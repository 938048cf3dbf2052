// The headers of JPEG streams (SOI to the first SOS) and JPEG 2000 codestreams (SIZ) walked
// before GDCM's codecs read them: they abort or crash on headers they did not plan for.
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

// What makes the JPEG stream at `data` unsafe for stb_image (image slices), or "": a scan whose
// components use a Huffman table (DC in a first DC or baseline scan, AC in an AC or baseline
// scan) or a quantization table that no segment before it defined. stb_image decodes with the
// uninitialized table then and asserts (Debian 12's libstb: found by fuzzing). Markers are found
// as stb_image finds them (fill bytes and stray bytes skipped; a scan's data ends at a marker
// that is not a restart); a stream cut short or without SOI passes, for stb_image to refuse.
std::string jpegScanTablesProblem(const uint8_t* data, size_t size);

// What is wrong with the header of the JPEG-LS stream at `data` for an image of `columns` x
// `rows` with `samples` samples a pixel of `bitsAllocated` bits, or "": its frame (SOF55) must
// give the same size and components, and a precision whose decoded samples fit (GDCM 3.0
// asserts when they overflow its buffer; found by fuzzing). Markers before it must be whole.
std::string jpegLsHeaderProblem(const uint8_t* data, size_t size, int64_t columns, int64_t rows,
                                int64_t samples, int64_t bitsAllocated);

// What is wrong with the main header of the JPEG 2000 codestream at `data` (SOC, then SIZ) for
// an image of `columns` x `rows` with `samples` samples a pixel, or "". GDCM 3.0 with OpenJPEG
// 2.5 (Debian 12) crashes freeing its decoder after a codestream whose image size disagrees with
// the DICOM header's, and GDCM's own walk over the markers reads past a segment longer than the
// stream (both found by fuzzing). Refused: an image size or offset other than the DICOM
// header's, tiles that do not cover it, other numbers of components, subsampled components,
// more than 16 bits a sample, and marker segments (up to SOD) that overrun the stream. Bytes
// that start no codestream (a JP2 box, a later fragment) pass.
std::string jpeg2000HeaderProblem(const uint8_t* data, size_t size, int64_t columns, int64_t rows,
                                  int64_t samples);

// Whether a DICOM transfer syntax UID is one of the JPEG (ISO 10918) ones GDCM decodes with
// that codec (not JPEG-LS or JPEG 2000).
bool isJpegTransferSyntax(const std::string& uid);
// Whether it is a JPEG-LS one (1.2.840.10008.1.2.4.80, .81).
bool isJpegLsTransferSyntax(const std::string& uid);
// Whether it is a JPEG 2000 one (1.2.840.10008.1.2.4.90 to .93).
bool isJpeg2000TransferSyntax(const std::string& uid);

}  // namespace ewa
