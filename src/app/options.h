// Options: everything the command line can set, parsed with CLI11.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>

#include "io/volume_loader.h"
#include "render/renderer.h"

namespace ewa {

struct Options {
  std::string file;       // volume file; empty: --synthetic or the default asset
  std::string synthetic;  // "sphere:64", ...
  std::string output;     // PNG path: render headless and exit
  int turntable = 0;      // > 0: that many frames over 360 degrees, --output a pattern or folder
  int fps = 30;           // frames per second of a turntable written as a video
  int tour = 0;           // > 0: that many frames through the camera bookmarks (--tour)
  std::string bookmarks;  // --bookmarks: the tour's file (default: NAME.bookmarks.json beside)
  std::string configDir;  // the window's settings folder; empty: defaultConfigDir()
  std::string split = "visible";  // ewaview-mpi's bricks: balanced by "visible" voxels or "voxels"
  std::vector<std::string> tfPresets;  // --tf-preset keys, applied in order to the function
  bool watch = false;                  // the window reloads the volume when its file changes
  std::string recordCameraPath;     // the window writes every camera it draws to this file on exit
  bool resolutionGiven = false;     // --resolution was given (overrides the saved window size)
  bool renderOptionsGiven = false;  // a render option was given (overrides the saved ones)
  bool info = false;                // print the volume's description as JSON and exit
  std::string saveVolume;           // --save-volume FILE.nrrd: write the volume as NRRD and exit
  bool stats = false;               // after --output, print the frame's statistics as one JSON line
  std::optional<glm::dvec2> pick;   // --pick X,Y: print what that pixel shows as JSON and exit
  int width = 800;
  int height = 600;
  std::optional<glm::dvec3> cameraPosition;
  std::optional<glm::dvec3> cameraFocalPoint;
  std::optional<glm::dvec3> cameraViewUp;
  double cameraViewAngle = 30.0;
  bool orthographic = false;
  bool axes = false;  // --axis: the orientation axes in the picture's corner
  RenderSettings render;
  std::string tfFile;
  std::string backend = "osmesa";
  std::string shaderDir;  // load shaders from this folder instead of the embedded ones
  LoadOptions load;       // --series, --frame, --channel
  // --channel all, or a list "0,2": channels overlaid in their colours (headless).
  bool overlay = false;
  std::vector<int> overlayChannels;  // the list's channels, the first in load.channel; empty: all
  // Where the window keeps an archive it opened unpacked (null headless: unpacked per load).
  std::shared_ptr<ArchiveCache> archives;
  // Plain raw input.
  std::string rawDims, rawType, rawSpacing = "1,1,1", rawEndian = "little";
};

// A number as typed, without trailing zeros ("12", "3.5"), for messages.
std::string numberText(double v);

// Outcome of parsing: run, or exit at once with `exitCode` (0 for --help/--version, 2 for
// a usage error, whose message has been printed to stderr).
struct ParseResult {
  bool run = true;
  int exitCode = 0;
};

ParseResult parseCommandLine(int argc, const char* const* argv, Options* options);
// What --help prints: the options in the table's groups (option_table.cpp).
std::string commandLineHelp();

// The option whose value (or one of its comma-separated numbers) reads as NaN, if any, else "":
// CLI11's Range checks compare, and NaN passes every comparison, so a NaN cutoff or kernel
// width would reach the renderer. ewaview and the benchmark programs refuse it before parsing.
std::string optionWithNan(int argc, const char* const* argv);

}  // namespace ewa
