// Front-to-back compositing of a perspective view's scaled slices into the intermediate image.
#pragma once

#include "core/intermediate_image.h"
#include "core/shear_warp_compositor.h"

namespace ewa {

// compositeSlices' loops for a perspective factorization (input.view->perspective): every
// intermediate pixel is one ray through the eye, sampling slice k at ((u - offsetI(k)) /
// scale(k), (v - offsetJ(k)) / scale(k)) bilinearly; standard (point table) or pre-integrated
// (pair table, the back sample kept per intermediate pixel for the next slab). Opacity is
// corrected per ray for its own distance between slices (ShearWarpFactorization::rayRatio) when
// the settings ask for it; the tables come uncorrected. Rows v = thread, thread + threads, ...
void compositePerspective(const CompositeInput& in, IntermediateImage& out, int thread, int threads,
                          CompositorBuffers& buffers);

}  // namespace ewa
