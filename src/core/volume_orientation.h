// Orientation: direction matrices kept rotations, and the camera that draws a volume in its frame.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/volume.h"

namespace ewa {

// True when the columns of `d` are unit length and pairwise orthogonal within `tolerance`.
bool isOrthonormal(const glm::dmat3& d, double tolerance = 1e-4);

// The orthonormal matrix nearest in spirit to `d`: Gram-Schmidt on its columns in order (the
// first axis keeps its direction, the second its plane), keeping the handedness of `d`.
// A singular `d` (or a non-finite one) gives the identity.
glm::dmat3 orthonormalized(const glm::dmat3& d);

// Voxel data with its placement, as a loader has it before it becomes a Volume.
struct OrientedGrid {
  std::array<int64_t, 3> dims{1, 1, 1};
  size_t elementSize = 1;
  std::vector<uint8_t>* bytes = nullptr;  // x fastest, dims product * elementSize bytes
  glm::dvec3 spacing{1.0};
  glm::dvec3 origin{0.0};
  glm::dmat3 direction{1.0};
};

// Leaves grid.direction a rotation without moving any voxel in world space: a non-orthonormal
// direction (gantry tilt, shear) is orthonormalized (so those voxels do move, with a warning), and
// a reflection (det < 0) is undone by reversing the data along the third axis (origin moved to the
// last slice, third column negated). Returns the notes to show the user (a warning for the
// orthonormalization, a note for the flip); empty when nothing changed.
std::vector<std::string> makeRotation(OrientedGrid& grid);

// The camera that, looking at the volume drawn in its own frame (origin + (i,j,k) * spacing, no
// direction), sees the picture `world` sees of it in world space: `world` moved by the inverse
// of the rigid map x -> origin + D (x - origin). D must be a rotation (Volume's invariant).
Camera cameraInVolumeFrame(const Camera& world, const Volume& volume);

}  // namespace ewa
