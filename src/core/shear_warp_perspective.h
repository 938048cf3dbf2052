// Front-to-back compositing of scaled slices (perspective or magnified) into the intermediate
// image.
#pragma once

#include "core/intermediate_image.h"
#include "core/shear_warp_compositor.h"

namespace ewa {

// compositeSlices' loops for a resampled factorization (input.view->resampled(): perspective,
// or parallel and magnified): every intermediate pixel is one ray (through the eye), sampling
// slice k at ((u - offsetI(k)) / scale(k), (v - offsetJ(k)) / scale(k)) bilinearly; standard
// (point table) or pre-integrated (pair table, the back sample kept per intermediate pixel for
// the next slab). Perspective views' opacity is corrected per ray for its own distance between
// slices (ShearWarpFactorization::rayRatio) when the settings ask for it, from uncorrected
// tables; parallel views' tables come corrected for their one ratio. Rows v = thread, thread +
// threads, ...
void compositePerspective(const CompositeInput& in, IntermediateImage& out, int thread, int threads,
                          CompositorBuffers& buffers);

}  // namespace ewa
