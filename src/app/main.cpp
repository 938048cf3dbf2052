// ewaview entry point: parse the command line, then --info, headless output or the window.
#include <iostream>
#include <string>

#include "app/headless.h"
#include "app/options.h"
#include "app/scene.h"
#include "ui/viewer.h"

namespace {

// Errors are one line on stderr (GL compile logs come with several): breaks become " | ".
std::string oneLine(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') {
      if (!out.empty() && out.back() != ' ' && out.back() != ':') out += " |";
      out += ' ';
    } else if (c != '\r') {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '|')) out.pop_back();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  ewa::Options options;
  const ewa::ParseResult parsed = ewa::parseCommandLine(argc, argv, &options);
  if (!parsed.run) return parsed.exitCode;
  try {
    ewa::Scene scene = ewa::loadScene(options);
    if (options.info) {
      std::cout << ewa::volumeInfoJson(scene.volume) << "\n";
      return 0;
    }
    if (options.render.renderer == ewa::RendererKind::ShearWarp && !options.orthographic)
      std::cerr << "ewaview: note: shear-warp renders parallel projection; the perspective camera "
                   "is drawn as the orthographic view of the same height at the focal point\n";
    if (!options.output.empty()) {
      ewa::renderHeadless(scene, options);
      return 0;
    }
    ewa::ViewerConfig config;
    config.width = options.width;
    config.height = options.height;
    config.camera = ewa::initialCamera(scene.volume, options);
    config.settings = options.render;
    config.shaderDir = options.shaderDir;
    config.volumeName = scene.name;
    return ewa::runViewer(scene.volume, scene.transferFunction, config);
  } catch (const std::exception& e) {
    std::cerr << "ewaview: " << oneLine(e.what()) << "\n";
    return 1;
  }
}
