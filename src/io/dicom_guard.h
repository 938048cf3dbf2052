// A structural check run before GDCM sees a file: no element may claim more bytes than remain.
#pragma once

#include <string>

namespace ewa {

// What checkDicomStructure found.
enum class DicomStructure {
  Plausible,  // every element's length fits in the file
  NotDicom,   // neither the "DICM" preamble nor a data set from byte 0: not read as DICOM
};

// Walks the elements of the file at `path` (Part 10 preamble and meta header, then the data
// set in its transfer syntax: implicit or explicit VR, little or big endian; a deflated data set
// inflated first, within dicomInflateLimit (dicom_inflate.h); or, without the preamble, a bare
// little-endian data set from byte 0 as GDCM reads one: ACR-NEMA files), entering sequences and
// items (at most 128 sequences deep: GDCM recurses into them until its stack overflows), and
// checks each defined length against the bytes left. GDCM sizes its buffers by those lengths
// before reading (up to 4 GiB for one element) and asserts (aborts) on items out of place, so
// such files must be caught here. Zero bytes after the last element are padding, passed where
// GDCM reads them. Throws LoadError naming the file when a DICOM file is cut short or corrupt,
// or is a big-endian ACR-NEMA file; returns NotDicom for other files, which never reach GDCM.
DicomStructure checkDicomStructure(const std::string& path);

}  // namespace ewa
