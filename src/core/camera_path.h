// CameraPath: a recorded sequence of camera moves, one frame each, for replaying interaction.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"

namespace ewa {

// One frame's move, relative to the camera of the previous frame, so one path fits every
// volume (the replay starts from the volume's default framing).
struct CameraStep {
  enum class Kind { Orbit, Dolly, Pan, Hold, Set };
  Kind kind = Kind::Hold;
  double a = 0.0;  // orbit: azimuth degrees; dolly: factor (> 1 closer); pan: right
  double b = 0.0;  // orbit: elevation degrees; pan: up
  Camera camera;   // set: the whole camera (a recorded path)
};

// Text format, one command per line, '#' starts a comment, an optional leading count repeats
// the command (one frame each):
//   orbit AZ EL      degrees about view-up and the right axis
//   dolly F          move the eye F times closer (F > 0)
//   pan DX DY        across the view, in units of the distance to the focal point
//   hold             a frame without a move
//   camera PX PY PZ FX FY FZ UX UY UZ ANGLE ORTHO
//                    this camera (position, focal point, view-up, view angle, 0/1): what the
//                    viewer's --record-camera-path writes; such a path fits one volume
// e.g. "30 orbit 3 0". Throws std::runtime_error("name:line: problem") on bad text.
std::vector<CameraStep> parseCameraPath(const std::string& text, const std::string& name);
// Reads and parses a file; throws std::runtime_error("path: problem").
std::vector<CameraStep> loadCameraPath(const std::string& path);

// The "camera ..." line (no newline) that sets `camera`, with 17 significant digits.
std::string cameraStepLine(const Camera& camera);

// Applies one step to `camera`.
void applyCameraStep(Camera& camera, const CameraStep& step);

}  // namespace ewa
