// Command-line parsing with CLI11, following f3d's option names.
#include "app/options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <vector>

#include "app/clip_options.h"
#include "app/option_binding.h"
#include "app/render_options.h"
#include "app/version.h"
#include "io/text_fields.h"
#include "io/volume_writer.h"
#include "platform/headless_context.h"

namespace ewa {

namespace {

// CLI11 reads "X,Y,Z" into a vector; this checks the count and copies it into a dvec3.
std::optional<glm::dvec3> toVec3(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return glm::dvec3(v[0], v[1], v[2]);
}

// --close-up: the close-up setting wherever the command line did not set the same thing itself.
// Before finishShadingOptions, which turns the text options into settings and rejects surface
// splats with post-classification, however it was asked for.
void applyCloseUp(const CLI::App& app, RenderOptionText* text, RenderSettings* settings) {
  RenderSettings closeUp;
  applyCloseUpSettings(&closeUp);
  if (app.count("--classification") == 0)
    text->classification = classificationModeName(closeUp.classification.mode);
  if (app.count("--slab-preintegration") == 0)
    text->slabPreintegration = closeUp.slabPreintegration ? "on" : "off";
  if (app.count("--slab-samples") == 0) settings->slabSamples = closeUp.slabSamples;
  if (app.count("--kernel-width") == 0) settings->kernelWidth = closeUp.kernelWidth;
  if (app.count("--cutoff") == 0) settings->cutoff = closeUp.cutoff;
}

}  // namespace

std::string numberText(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string optionWithNan(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    std::string name = argv[i], value;
    if (name.size() < 2 || name[0] != '-') continue;
    const size_t eq = name.find('=');
    if (eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    } else if (i + 1 < argc) {
      value = argv[i + 1];
    }
    size_t start = 0;
    while (start <= value.size()) {
      const size_t end = std::min(value.find(',', start), value.size());
      const std::string piece = value.substr(start, end - start);
      char* rest = nullptr;
      const double number = std::strtod(piece.c_str(), &rest);
      if (!piece.empty() && rest && *rest == '\0' && std::isnan(number)) return name;
      start = end + 1;
    }
  }
  return "";
}

namespace {

// What CLI11 reads as text or lists, turned into Options after the parse.
struct ParsedText {
  std::vector<double> pick, pos, focal, up, bg, spacing;
  std::vector<int> res;
  std::string channel, filter, mode, lowPass = "auto", renderer, lookup, correction, buffers;
  bool closeUp = false, allowOutsideData = false;
  RenderOptionText render;
  ClipOptionText clip;
};

// Every option, in the table's order (option_table.cpp gives their help, groups and checks).
void addOptions(CLI::App& app, Options* o, ParsedText* t) {
  addHelpAndVersion(app, std::string("ewaview ") + versionString());
  app.formatter(std::make_shared<GroupedHelpFormatter>());
  // Given twice (a copied view pasted after one's own options), the last one counts.
  constexpr auto kLast = CLI::MultiOptionPolicy::TakeLast;
  addTableOption(app, "file", o->file);
  addTableOption(app, "--synthetic", o->synthetic);
  addTableOption(app, "--series", o->load.series);
  addTableOption(app, "--frame", o->load.frame);
  addTableOption(app, "--channel", t->channel);
  addTableOption(app, "--level", o->load.level);
  addTableOption(app, "--dataset", o->load.dataset);
  addTableOption(app, "--spacing", t->spacing)->delimiter(',')->expected(3);
  auto* rawDims = addTableOption(app, "--raw-dims", o->rawDims);
  addTableOption(app, "--raw-type", o->rawType)->needs(rawDims);
  addTableOption(app, "--raw-spacing", o->rawSpacing)->needs(rawDims);
  addTableOption(app, "--raw-endian", o->rawEndian)->needs(rawDims);
  addTableFlag(app, "--allow-outside-data", t->allowOutsideData);
  addTableFlag(app, "--watch", o->watch);
  addTableFlag(app, "--info", o->info);
  addTableOption(app, "--output", o->output);
  addTableOption(app, "--resolution", t->res)
      ->delimiter(',')
      ->expected(2)
      ->multi_option_policy(kLast);
  addTableFlag(app, "--stats", o->stats);
  addTableOption(app, "--turntable", o->turntable);
  addTableOption(app, "--tour", o->tour);
  addTableOption(app, "--bookmarks", o->bookmarks);
  addTableOption(app, "--fps", o->fps);
  addTableOption(app, "--pick", t->pick)->delimiter(',')->expected(2);
  addTableOption(app, "--save-volume", o->saveVolume);
  addTableOption(app, "--camera-position", t->pos)
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(kLast);
  addTableOption(app, "--camera-focal-point", t->focal)
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(kLast);
  addTableOption(app, "--camera-view-up", t->up)
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(kLast);
  addTableOption(app, "--camera-view-angle", o->cameraViewAngle)->multi_option_policy(kLast);
  addTableFlag(app, "--camera-orthographic", o->orthographic);
  addTableFlag(app, "--axis", o->axes);
  addTableOption(app, "--record-camera-path", o->recordCameraPath);
  addTableOption(app, "--tf", o->tfFile);
  addTableOption(app, "--tf-preset", o->tfPresets)
      ->expected(1)  // one a time, so a file named after it is not taken for a preset
      ->allow_extra_args(false)
      ->take_all();
  t->renderer = rendererKindName(o->render.renderer);
  addTableOption(app, "--renderer", t->renderer);
  t->mode = renderModeName(o->render.mode);
  addTableOption(app, "--render-mode", t->mode);
  t->filter = filterModeName(o->render.filter);
  addTableOption(app, "--filter", t->filter);
  addTableOption(app, "--kernel-width", o->render.kernelWidth);
  addTableOption(app, "--cutoff", o->render.cutoff);
  addTableOption(app, "--depth-cutoff", o->render.depthCutoff);
  addTableOption(app, "--low-pass", t->lowPass);
  addTableFlag(app, "--close-up", t->closeUp);
  addTableOption(app, "--slab-thickness", o->render.slabThickness);
  addTableOption(app, "--background", t->bg)->delimiter(',')->expected(3);
  addClipOptions(app, t->clip);
  addShadingOptions(app, o->render, t->render);
  addTableFlag(app, "--preintegrated", o->render.shearWarp.preintegrated);
  t->lookup = tableLookupName(o->render.shearWarp.lookup);
  addTableOption(app, "--table-lookup", t->lookup);
  t->correction = o->render.shearWarp.opacityCorrection ? "on" : "off";
  addTableOption(app, "--opacity-correction", t->correction);
  t->buffers = bufferSlicesName(o->render.shearWarp.buffers);
  addTableOption(app, "--buffer-slices", t->buffers);
  addTableOption(app, "--intermediate-scale", o->render.shearWarp.intermediateScale);
  addTableOption(app, "--backend", o->backend);
  addTableOption(app, "--shader-dir", o->shaderDir);
  addTableOption(app, "--config-dir", o->configDir);
  addTableOption(app, "--split", o->split);
}

const char* const kAbout =
    "ewaview: a volume viewer built on EWA volume splatting.\n"
    "Without --output it opens a window; with --output it renders headless and exits.";

}  // namespace

std::string commandLineHelp() {
  CLI::App app{kAbout, "ewaview"};
  Options options;
  ParsedText text;
  addOptions(app, &options, &text);
  return app.help();
}

ParseResult parseCommandLine(int argc, const char* const* argv, Options* o) {
  CLI::App app{kAbout, "ewaview"};
  ParsedText text;
  addOptions(app, o, &text);
  const std::vector<double>& pick = text.pick;
  const std::vector<double>& spacing = text.spacing;
  const std::vector<double>& bg = text.bg;
  const std::vector<int>& res = text.res;
  const std::string& channel = text.channel;
  if (const std::string nan = optionWithNan(argc, argv); !nan.empty()) {
    std::cerr << "ewaview: " << nan << ": not a finite number (see --help)\n";
    return {false, 2};
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    app.exit(e);
    return {false, 0};
  } catch (const CLI::ParseError& e) {
    std::cerr << "ewaview: " << e.what() << " (see --help)\n";
    return {false, 2};
  }
  auto usage = [](const std::string& message) {
    std::cerr << "ewaview: " << message << " (see --help)\n";
    return ParseResult{false, 2};
  };
  // The last of several counts, but each must hold its own number of values ("10,10,5" is
  // wrong, not the last two of three). CLI11 keeps every value; the words say how many times.
  for (const auto& [name, values] : {std::pair<std::string, size_t>{"--resolution", 2},
                                     {"--camera-position", 3},
                                     {"--camera-focal-point", 3},
                                     {"--camera-view-up", 3}}) {
    size_t given = 0;
    for (int a = 1; a < argc; ++a) {
      const std::string word = argv[a];
      given += word == name || word.rfind(name + "=", 0) == 0;
    }
    if (app.get_option(name)->results().size() != given * values)
      return usage(name + ": give " + std::to_string(values) + " numbers, comma-separated");
  }
  if (app.count("--backend") == 0) {
    try {
      o->backend = platform::defaultHeadlessBackend();
    } catch (const std::invalid_argument& e) {
      return usage(e.what());
    }
  }
  if (!channel.empty() && channel == "all") {
    o->overlay = true;
  } else if (!channel.empty()) {
    std::vector<int64_t> list;  // comma-separated, every part a number
    bool numbers = true;
    for (size_t start = 0; numbers;) {
      const size_t comma = std::min(channel.find(',', start), channel.size());
      int64_t c = 0;
      numbers = parseInt64(channel.substr(start, comma - start), c) && c >= 0 && c <= (1 << 20);
      list.push_back(c);
      if (comma == channel.size()) break;
      start = comma + 1;
    }
    std::vector<int64_t> sorted = list;
    std::sort(sorted.begin(), sorted.end());
    if (!numbers || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return usage("--channel " + channel +
                   ": give a channel number from 0, a list of different ones (0,2) or 'all'");
    o->load.channel = int(list.front());
    if (list.size() > 1) {
      o->overlay = true;
      o->overlayChannels.assign(list.begin(), list.end());
    }
  }
  if (o->overlay && (!o->tfFile.empty() || o->pick || !o->saveVolume.empty() || o->info))
    return usage("--channel " + channel +
                 ": channels overlaid, not with --tf (each channel's own NAME.cC.tf.json is read), "
                 "--pick, --save-volume or --info");
  if (!o->file.empty() && !o->synthetic.empty())
    return usage("give a FILE or --synthetic, not both");
  if (!o->rawDims.empty() && o->rawType.empty()) return usage("--raw-dims needs --raw-type");
  if (!o->rawDims.empty() && o->file.empty()) return usage("--raw-dims needs a FILE");
  // A coarser level of anything but an OME-Zarr image would silently be the full resolution
  // (level 0, which every volume has).
  if (o->load.level != 0) {
    const std::string level = "--level " + std::to_string(o->load.level);
    if (!o->synthetic.empty())
      return usage(level + " picks a level of an OME-Zarr pyramid, not of --synthetic " +
                   o->synthetic);
    if (o->file.empty() || !o->rawDims.empty() || !mayHoldZarrLevels(o->file))
      return usage((o->file.empty() ? std::string("the default volume") : o->file) + ": " + level +
                   " picks a level of an OME-Zarr pyramid, and this is not an OME-Zarr "
                   "image");
  }
  if (o->turntable > 0 && o->output.empty()) return usage("--turntable needs --output");
  if (o->tour > 0 && (o->output.empty() || o->turntable > 0))
    return usage("--tour needs --output and is not a --turntable");
  if (!o->bookmarks.empty() && o->tour == 0) return usage("--bookmarks goes with --tour");
  if (o->stats && (o->output.empty() || o->turntable > 0 || o->tour > 0))
    return usage("--stats needs --output (one picture, no --turntable or --tour)");
  // "series/" and "series" are one folder (and name one bookmarks file beside it).
  while (o->file.size() > 1 && o->file.back() == '/') o->file.pop_back();
  o->resolutionGiven = !res.empty();
  // Every option the settings file also holds (main.cpp takes the saved ones only when none is
  // given): one missing here was silently overridden by the saved value in the window.
  for (const char* name :
       {"--filter", "--render-mode", "--cutoff", "--depth-cutoff", "--kernel-width",
        "--classification", "--slab-preintegration", "--slab-samples", "--low-pass", "--prefilter",
        "--post-normals", "--slab-thickness", "--slab-resolution", "--background", "--close-up"})
    o->renderOptionsGiven |= app.count(name) > 0;
  if (!res.empty()) {
    o->width = res[0];
    o->height = res[1];
  }
  if (!o->saveVolume.empty()) {
    if (!o->output.empty() || o->turntable > 0 || o->tour > 0 || !pick.empty())
      return usage(
          "--save-volume writes the volume and exits: not with --output, --turntable "
          "or --pick");
    if (!savedVolumeFormat(o->saveVolume))
      return usage("--save-volume " + o->saveVolume + ": the file must end in " +
                   savedVolumeExtensionsText());
  }
  if (!pick.empty()) {
    if (o->info || !o->output.empty())
      return usage("--pick prints JSON and exits: not with --info or --output");
    if (pick[0] < 0.0 || pick[1] < 0.0 || pick[0] >= o->width || pick[1] >= o->height)
      return usage("--pick " + numberText(pick[0]) + "," + numberText(pick[1]) +
                   " lies outside the " + std::to_string(o->width) + "x" +
                   std::to_string(o->height) + " picture");
    o->pick = glm::dvec2(pick[0], pick[1]);
  }
  for (double s : spacing)
    if (!(s > 0.0) || !std::isfinite(s) || s > 1e300)
      return usage("--spacing " + numberText(spacing[0]) + "," + numberText(spacing[1]) + "," +
                   numberText(spacing[2]) + ": each must be a positive number");
  o->load.spacing = toVec3(spacing);
  if (text.allowOutsideData) o->load.dataFiles = DataFileScope::Anywhere;
  o->cameraPosition = toVec3(text.pos);
  o->cameraFocalPoint = toVec3(text.focal);
  o->cameraViewUp = toVec3(text.up);
  if (!bg.empty()) o->render.background = glm::dvec3(bg[0], bg[1], bg[2]);
  parseFilterMode(text.filter, &o->render.filter);
  parseRenderMode(text.mode, &o->render.mode);
  if (text.closeUp) applyCloseUp(app, &text.render, &o->render);
  if (const std::string e = finishShadingOptions(text.render, &o->render); !e.empty())
    return usage(e);
  if (const std::string e = finishClipOptions(text.clip, &o->render.clip); !e.empty())
    return usage(e);
  if (o->tour > 0 && o->render.clip.active())
    return usage(
        "--tour takes the crop box and planes of its bookmarks: leave --crop and "
        "--clip-plane out");
  if (!o->saveVolume.empty() && !o->render.clip.planes.empty())
    return usage(
        "--save-volume cuts the volume to --crop's box; a clipping plane cannot cut a grid: "
        "leave --clip-plane out");
  if (text.lowPass != "auto") o->render.lowPass = std::stod(text.lowPass);  // checked above
  parseRendererKind(text.renderer, &o->render.renderer);
  parseTableLookup(text.lookup, &o->render.shearWarp.lookup);
  parseBufferSlices(text.buffers, &o->render.shearWarp.buffers);
  o->render.shearWarp.opacityCorrection = text.correction == "on";
  return {true, 0};
}

}  // namespace ewa
