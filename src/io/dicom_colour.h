// DICOM colour spaces: which are read where, Y'CbCr to RGB, and uncompressed 4:2:2 chroma.
#pragma once

#include <gdcmTransferSyntax.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// YBR_FULL or YBR_FULL_422: full-range Y, Cb, Cr converted to RGB here.
bool isYbrFull(const std::string& photometric);
// The colour spaces of three samples a pixel ewaview reads: RGB, YBR_FULL(_422), YBR_RCT and
// YBR_ICT (which JPEG 2000's inverse transform returns as RGB).
bool isColourSpace(const std::string& photometric);

// What is wrong with colour space `photometric` in transfer syntax `syntax` (its UID;
// `encapsulated`: compressed), or "": YBR_FULL_422 other than in JPEG or uncompressed, YBR_RCT
// and YBR_ICT outside JPEG 2000. Checked before GDCM reads a file too (dicom_guard), since its
// reader decodes RLE and asserts on a colour space whose size disagrees with the codec's.
std::string colourCodingProblem(const std::string& photometric, const std::string& syntax,
                                bool encapsulated);
// Throws LoadError naming the file for a colour space outside the coding it exists in:
// YBR_FULL_422 other than in JPEG or uncompressed, YBR_RCT and YBR_ICT outside JPEG 2000
// (GDCM's raw decoder asserts on them).
void checkColourCoding(const DicomSlice& slice, gdcm::TransferSyntax ts);

// One RGB component (0 red, 1 green, 2 blue) of full-range Y, Cb, Cr (DICOM PS3.3 C.7.6.3.1.2,
// the chroma offset half the range of `bits` bits), rounded and kept within that range.
double rgbOfYbr(double y, double cb, double cr, int component, int64_t bits);

// Uncompressed 8-bit YBR_FULL_422 (PS3.5 8.2.1: each two pixels of a row stored Y1 Y2 Cb Cr):
// RGB component `component` of `count` pixels, rows `columns` wide (an even number), the chroma
// shared by each pair. Throws LoadError("<file>: ...") for an odd width or too few bytes.
std::vector<double> rgbOfYbr422(const std::string& file, const uint8_t* bytes, uint64_t length,
                                int64_t columns, uint64_t count, int component);

}  // namespace ewa
