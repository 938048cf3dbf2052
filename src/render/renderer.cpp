// Names of the render modes, for the command line and the window.
#include "render/renderer.h"

namespace ewa {

const char* renderModeName(RenderMode mode) {
  switch (mode) {
    case RenderMode::Composite: return "composite";
    case RenderMode::XRay: return "xray";
  }
  return "?";
}

bool parseRenderMode(const std::string& text, RenderMode* mode) {
  if (text == "composite") *mode = RenderMode::Composite;
  else if (text == "xray") *mode = RenderMode::XRay;
  else return false;
  return true;
}

}  // namespace ewa
