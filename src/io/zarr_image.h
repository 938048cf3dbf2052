// An OME-Zarr image (or bare Zarr array) opened at one pyramid level: which array, which axes.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "io/file_bytes.h"
#include "io/zarr_metadata.h"

namespace ewa {

struct ZarrImage {
  std::string path;         // what the user named: messages start with it
  std::string attributes;   // the image's .zattrs or the bare array's .zarray: chunk files
                            // must lie in its folder (checkDataFileScope)
  std::string arrayFolder;  // the level's array
  std::string levelName;    // the level's path as the file names it ("0"), for messages
  ZarrArrayMeta meta;
  int level = 0, levels = 1;
  // Roles of the array's axes: -1 where there is none (z of a 2D image: one slice).
  int timeAxis = -1, channelAxis = -1;
  std::array<int, 3> spaceAxes{-1, -1, -1};  // x, y, z
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};
  std::string unit;
  std::vector<std::string> notes;

  int frames() const { return timeAxis < 0 ? 1 : int(meta.shape[size_t(timeAxis)]); }
  int channels() const { return channelAxis < 0 ? 1 : int(meta.shape[size_t(channelAxis)]); }
  std::array<int64_t, 3> dims() const;
};

// Opens `path` (a folder ending .zarr, an array's folder, or its .zattrs, .zgroup or .zarray
// file) at pyramid level `level`. An OME-NGFF image's level is a dataset of its multiscales;
// a bioformats2raw folder opens its first image ("0"); a bare array has level 0 alone.
// Throws LoadError.
ZarrImage openZarrImage(const std::string& path, int level, DataFileScope scope);

}  // namespace ewa
