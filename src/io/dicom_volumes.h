// DICOM series holding several volumes at the same positions: picking one (--frame).
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/dicom_series.h"

namespace ewa {

// The slices of volume `volume` of a series (or an enhanced file's frames) that holds several
// volumes at the same slice positions: diffusion directions, echoes, time points. Slices are
// grouped by their position along the slice normal; when there are at least two positions and
// each holds the same number N of slices, the k-th of each (by InstanceNumber, then frame, then
// file name) belongs to volume k, and a note says so. Where positions hold unequal numbers
// (a file missing, a scan cut short), volumes are told apart by the images' numbers
// (InstanceNumber, or an enhanced file's frame index), numbered one volume after another or
// slice by slice, and the note names the volumes short of slices, whose slices are returned
// as they are (sortDicomSlices fills a gap inside); unnumbered or numbered alike, LoadError. A
// series of one volume is returned as it is; `volume` out of range throws LoadError naming `path`.
// Slices at one position only, or without a position or a shared orientation, are left for
// sortDicomSlices (and volume must be 0). `count`, when given, gets the number of volumes (1 for a
// series of one).
std::vector<DicomSlice> selectDicomVolume(const std::string& path, std::vector<DicomSlice> slices,
                                          int volume, std::vector<std::string>& notes,
                                          int* count = nullptr);

// A cine (or a time series of one slice): single-frame images that all lie at one position, at
// least two of them. Stacks them in InstanceNumber order (then file name), adds a note saying
// so and returns the step between them: 1 along the slice normal. Returns nullopt, leaving
// `slices` alone, for anything else.
std::optional<glm::dvec3> stackOnePosition(std::vector<DicomSlice>& slices,
                                           std::vector<std::string>& notes);

}  // namespace ewa
