// The continuous image of a one-voxel-thick volume (a sheet) by integration along real
// perspective rays on the CPU: the quality benchmark's reference, made without the EWA
// footprint code (no Jacobian, no screen-space conic, no slabs).
#pragma once

#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/image_metrics.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa {

// One ray per pixel centre of a width x height image (top row first, RGB) of `camera`'s
// perspective view. The volume is reconstructed as the renderer's kernels are meant to be: each
// voxel a 3D Gaussian of covariance diag((kernelWidth * spacing)^2) (the renderer's kernel
// width; the mass stays the voxel's) and mass tau(v) * sx * sy * sz, with the
// transfer function's colour. Along a ray every kernel is a 1D Gaussian in the ray parameter
// with the same width (all kernels share the covariance), so the extinction and emission along
// the ray are the kernels' weights (exact line integrals) at their means convolved with that
// Gaussian, integrated front to back (emission-absorption) on a grid of a quarter of its
// standard deviation, and composited over `background`. Kernels whose Mahalanobis distance to
// the ray exceeds 4.5 are left out (weight below e^-10). Runs on `threads` threads (0: all cores).
// Throws std::invalid_argument unless the volume is one voxel thick along z, the camera is
// perspective and the kernel width positive.
FloatImage sheetRayImage(const Volume& sheet, const TransferFunction& tf, const Camera& camera,
                         int width, int height, const glm::dvec3& background,
                         double kernelWidth = 1.0, int threads = 0);

}  // namespace ewa
