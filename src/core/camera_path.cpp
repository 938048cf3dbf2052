// CameraPath: parsing the text format and applying its steps.
#include "core/camera_path.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ewa {

namespace {

[[noreturn]] void fail(const std::string& name, int line, const std::string& problem) {
  throw std::runtime_error(name + ":" + std::to_string(line) + ": " + problem);
}

// Reads exactly `count` finite numbers from the rest of the line.
void readNumbers(std::istringstream& in, int count, double* out, const std::string& name, int line,
                 const std::string& command) {
  for (int n = 0; n < count; ++n) {
    if (!(in >> out[n]) || !std::isfinite(out[n]))
      fail(name, line, command + " needs " + std::to_string(count) + " numbers");
  }
  std::string extra;
  if (in >> extra) fail(name, line, "unexpected '" + extra + "' after " + command);
}

}  // namespace

std::vector<CameraStep> parseCameraPath(const std::string& text, const std::string& name) {
  constexpr long kMaxFrames = 1000000;
  std::vector<CameraStep> steps;
  std::istringstream lines(text);
  std::string raw;
  int lineNo = 0;
  while (std::getline(lines, raw)) {
    ++lineNo;
    const size_t hash = raw.find('#');
    std::istringstream in(raw.substr(0, hash));
    std::string word;
    if (!(in >> word)) continue;  // blank or comment
    long repeat = 1;
    if (std::isdigit(static_cast<unsigned char>(word[0]))) {
      char* end = nullptr;
      repeat = std::strtol(word.c_str(), &end, 10);
      if (*end != '\0' || repeat < 1 || repeat > kMaxFrames)
        fail(name, lineNo, "bad repeat count '" + word + "'");
      if (!(in >> word)) fail(name, lineNo, "a repeat count needs a command");
    }
    CameraStep step;
    double v[2] = {0.0, 0.0};
    if (word == "orbit") {
      step.kind = CameraStep::Kind::Orbit;
      readNumbers(in, 2, v, name, lineNo, word);
    } else if (word == "dolly") {
      step.kind = CameraStep::Kind::Dolly;
      readNumbers(in, 1, v, name, lineNo, word);
      if (!(v[0] > 0.0)) fail(name, lineNo, "dolly factor must be positive");
    } else if (word == "pan") {
      step.kind = CameraStep::Kind::Pan;
      readNumbers(in, 2, v, name, lineNo, word);
    } else if (word == "hold") {
      step.kind = CameraStep::Kind::Hold;
      readNumbers(in, 0, v, name, lineNo, word);
    } else if (word == "camera") {
      step.kind = CameraStep::Kind::Set;
      double c[11];
      readNumbers(in, 11, c, name, lineNo, word);
      step.camera.position = {c[0], c[1], c[2]};
      step.camera.focalPoint = {c[3], c[4], c[5]};
      step.camera.viewUp = {c[6], c[7], c[8]};
      step.camera.viewAngleDeg = c[9];
      step.camera.orthographic = c[10] != 0.0;
      if (!step.camera.valid()) fail(name, lineNo, "camera is not a valid view");
    } else {
      fail(name, lineNo, "unknown command '" + word + "'");
    }
    step.a = v[0];
    step.b = v[1];
    if (long(steps.size()) + repeat > kMaxFrames) fail(name, lineNo, "too many frames");
    steps.insert(steps.end(), size_t(repeat), step);
  }
  if (steps.empty()) throw std::runtime_error(name + ": no camera steps");
  return steps;
}

std::vector<CameraStep> loadCameraPath(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot open");
  std::stringstream text;
  text << file.rdbuf();
  return parseCameraPath(text.str(), path);
}

std::string cameraStepLine(const Camera& c) {
  char line[512];
  std::snprintf(
      line, sizeof line, "camera %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d",
      c.position.x, c.position.y, c.position.z, c.focalPoint.x, c.focalPoint.y, c.focalPoint.z,
      c.viewUp.x, c.viewUp.y, c.viewUp.z, c.viewAngleDeg, c.orthographic ? 1 : 0);
  return line;
}

void applyCameraStep(Camera& camera, const CameraStep& step) {
  switch (step.kind) {
    case CameraStep::Kind::Orbit:
      camera.orbit(step.a, step.b);
      break;
    case CameraStep::Kind::Dolly:
      camera.dolly(step.a);
      break;
    case CameraStep::Kind::Pan: {
      const double d = camera.distance();
      camera.pan(step.a * d, step.b * d);
      break;
    }
    case CameraStep::Kind::Set:
      camera = step.camera;
      break;
    case CameraStep::Kind::Hold:
      break;
  }
}

}  // namespace ewa
