// Camera tours: the views between stops (the window's camera bookmarks) for a video that flies
// from one to the next (--tour, the window's "Tour").
#pragma once

#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"

namespace ewa {

struct TourStop {
  Camera camera;
  ClipRegion clip;
};

// The view `t` of the way through the stops (t in [0, 1], clamped): every leg from one stop to
// the next takes an equal share of t, eased in and out (smoothstep), so the view slows into
// each stop and leaves it again. Along a leg the focal point moves on a straight line, the
// orientation turns by the shortest rotation (quaternion slerp of the camera's rotation), the
// distance changes geometrically (a zoom at an even pace) and the view angle linearly;
// orthographic projection and the clipping planes switch half way; the crop box moves between
// the two boxes when both stops have one. One stop: that stop. Throws std::invalid_argument
// without stops.
TourStop tourStop(const std::vector<TourStop>& stops, double t);

// Frame `index` of `count` frames through the stops: the first frame is the first stop, the last
// frame the last one (t = index / (count - 1); one frame: the first stop).
TourStop tourFrame(const std::vector<TourStop>& stops, int index, int count);

}  // namespace ewa
