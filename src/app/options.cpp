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
#include "app/render_options.h"
#include "app/version.h"
#include "core/kernel_lattice.h"
#include "core/transfer_function_presets.h"
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

ParseResult parseCommandLine(int argc, const char* const* argv, Options* o) {
  CLI::App app{
      "ewaview: a volume viewer built on EWA volume splatting.\n"
      "Without --output it opens a window; with --output it renders headless and exits.",
      "ewaview"};
  app.set_version_flag("--version", std::string("ewaview ") + versionString());
  app.add_option(
      "file", o->file,
      "Volume file (.nrrd .nhdr .mhd .mha .dat .vti .vtk .nii .nii.gz .hdr .img .dcm .tif "
      ".tiff .ome .slc .mrc .map .rec), a folder of DICOM, TIFF or .png .jpg .bmp .pgm slices, "
      "an archive of one (.zip .tar .tar.gz .7z ...), or raw with --raw-*");
  app.add_option("--synthetic", o->synthetic,
                 "Synthetic volume: marschner-lobb[:N], sphere[:N], checkerboard, zebra[:RATIO]");
  app.add_option(
      "-o,--output", o->output,
      "Render headless to this PNG and exit (with --turntable or --tour: frames or a video)");
  app.add_option("--turntable", o->turntable,
                 "Render N frames over 360 degrees about view-up; --output is a pattern with one "
                 "%d (frame_%03d.png), a folder, or a video (.mp4: H.264, .webm: VP9)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--tour", o->tour,
                 "Render N frames flying through the camera bookmarks in order (the window's, "
                 "with their crop boxes and planes), resting at each; --output as --turntable")
      ->check(CLI::Range(2, 100000));
  app.add_option("--bookmarks", o->bookmarks,
                 "The camera bookmarks --tour flies through (default: the window's for the "
                 "volume, NAME.bookmarks.json beside it or under the settings folder)");
  app.add_option("--fps", o->fps, "Frames per second of a --turntable or --tour video (default 30)")
      ->check(CLI::Range(1, 240));
  app.add_option("--config-dir", o->configDir,
                 "Window settings folder (default $EWAVIEW_CONFIG_DIR, else "
                 "$XDG_CONFIG_HOME/ewaview or ~/.config/ewaview)");
  app.add_flag("--watch", o->watch,
               "Window: reload the volume, keeping the view and transfer function, whenever its "
               "file changes (a simulation or scanner writing it; also F5 and the panel)");
  app.add_option("--record-camera-path", o->recordCameraPath,
                 "Window: write the cameras of the session to this file on exit, for "
                 "ewaview-interact-bench --path");
  app.add_flag("--stats", o->stats,
               "With --output: print the frame's statistics as one JSON line (times, splats, "
               "gpu_bytes, gpu_bytes_per_splat, peak_rss)");
  app.add_flag("--info", o->info,
               "Print dims, spacing, type, value range, direction and notes as JSON and exit");
  app.add_option("--save-volume", o->saveVolume,
                 "Write the volume as opened (any format, after --frame, --channel, --series, "
                 "--spacing; with --crop only the box's voxels) to this file and exit: .nrrd "
                 "(gzip), .nii or .nii.gz (NIfTI-1), .mha or .mhd with .raw (MetaImage), .tif "
                 "or .tiff (OME-TIFF)");
  std::vector<double> pick;
  app.add_option("--pick", pick,
                 "Print what pixel X,Y (column, row from the top left) of the --resolution "
                 "picture shows (world point, voxel, value) as JSON and exit")
      ->delimiter(',')
      ->expected(2);
  app.add_option("--series", o->load.series,
                 "DICOM: open the series with this SeriesInstanceUID (UID#2, ... a part of one "
                 "that mixes sizes, orientations or multi-frame files)");
  app.add_option("--frame", o->load.frame,
                 "4D NIfTI or NRRD, an OME-TIFF's or ImageJ hyperstack's time point, or a DICOM "
                 "series of several volumes at the same positions: open this volume (default 0)")
      ->check(CLI::Range(0, 1 << 30));
  std::string channel;
  app.add_option("--channel", channel,
                 "Colour or vector data (TIFF, DICOM, image slices and NIfTI: 0 red, 1 green, 2 "
                 "blue; MetaImage channels, VTK components and vectors, a 4D NRRD's colour or "
                 "vector axis): open this channel (default 0); 'all' or a list (0,2): those "
                 "channels overlaid, each in its colour, the colours added (headless: --output, "
                 "--turntable, --tour)");
  std::vector<int> res;
  // Given twice (a copied view pasted after one's own options), the last one counts.
  constexpr auto kLast = CLI::MultiOptionPolicy::TakeLast;
  app.add_option("--resolution", res, "Image size W,H (default 800,600)")
      ->delimiter(',')
      ->expected(2)
      ->multi_option_policy(kLast)
      ->check(CLI::Range(1, 16384));
  std::vector<double> pos, focal, up, bg, spacing;
  app.add_option("--spacing", spacing,
                 "Voxel spacing X,Y,Z replacing the file's (image stacks have none; raw files: "
                 "--raw-spacing)")
      ->delimiter(',')
      ->expected(3);
  bool allowOutsideData = false;
  app.add_flag("--allow-outside-data", allowOutsideData,
               "Let a detached header (.mhd, .nhdr, .dat) name data files outside its own folder");
  app.add_option("--camera-position", pos, "Camera position X,Y,Z")
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(kLast);
  app.add_option("--camera-focal-point", focal, "Camera focal point X,Y,Z")
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(kLast);
  app.add_option("--camera-view-up", up, "Camera view-up X,Y,Z")
      ->delimiter(',')
      ->expected(3)
      ->multi_option_policy(kLast);
  app.add_option("--camera-view-angle", o->cameraViewAngle,
                 "Vertical view angle in degrees (default 30)")
      ->multi_option_policy(kLast)
      ->check(CLI::Range(0.01, 179.0));
  app.add_flag("--camera-orthographic", o->orthographic, "Orthographic projection");
  app.add_flag("--axis", o->axes,
               "Draw the orientation axes in the picture's bottom-right corner (X, Y, Z; L, P, S "
               "for patient axes); the window shows them unless switched off (X key)");
  std::string filter = "ewa", mode = "composite";
  app.add_option("--filter", filter, "Splat filter: ewa (default), swan, plain")
      ->check(CLI::IsMember({"ewa", "swan", "plain"}));
  app.add_option("--render-mode", mode, "composite (default), xray or mip")
      ->check(CLI::IsMember({"composite", "xray", "mip"}));
  RenderOptionText renderText;
  addShadingOptions(app, o->render, renderText);
  ClipOptionText clipText;
  std::string lowPassText = "auto";
  addClipOptions(app, clipText);
  app.add_option("--cutoff", o->render.cutoff, "Footprint cutoff r = dx^T Q dx (default 5)")
      ->check(CLI::Range(0.25, 64.0));
  app.add_option("--depth-cutoff", o->render.depthCutoff,
                 "Kernels' depth extent in squared sigmas, 0.25 and up or inf (default 1)")
      ->check(CLI::Range(0.25, double(INFINITY)));
  app.add_option("--kernel-width", o->render.kernelWidth,
                 "Kernel sigma in voxel spacings, 0.3 to 2 (default 0.7)")
      ->check(CLI::Range(kMinKernelWidth, kMaxKernelWidth));
  app.add_option("--low-pass", lowPassText,
                 "EWA's screen low-pass filter: its variance in pixels^2, 0.1 to 1, or auto "
                 "(default auto: 1, the paper's, in every mode)")
      ->check(CLI::IsMember({"auto"}) | CLI::Range(0.1, 1.0));
  bool closeUp = false;
  app.add_flag("--close-up", closeUp,
               "Close-up setting, today the defaults: --classification post --slab-preintegration "
               "on --kernel-width 0.7 --cutoff 5; options given beside it win");
  app.add_option("--slab-thickness", o->render.slabThickness,
                 "Slab thickness in voxel depths along the view, 0.25 and up (default 2)")
      ->check(CLI::Range(0.25, 1000.0));
  std::string rendererName = "splat", lookup = "nearest", correction = "on", buffers = "slice";
  app.add_option("--renderer", rendererName,
                 "splat (default, GPU EWA splatting) or shearwarp (CPU)")
      ->check(CLI::IsMember({"splat", "shearwarp"}));
  app.add_flag("--preintegrated", o->render.shearWarp.preintegrated,
               "Shear-warp: pre-integrated slabs between slices");
  app.add_option("--table-lookup", lookup,
                 "Shear-warp pre-integration lookup: nearest (default) or bilinear")
      ->check(CLI::IsMember({"nearest", "bilinear"}));
  app.add_option("--opacity-correction", correction,
                 "Shear-warp opacity and colour correction for the view's sample distance: on "
                 "(default) or off")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--buffer-slices", buffers,
                 "Shear-warp buffer slices: slice (two slice-sized, default) or image (one "
                 "intermediate-image-sized)")
      ->check(CLI::IsMember({"slice", "image"}));
  app.add_option("--intermediate-scale", o->render.shearWarp.intermediateScale,
                 "Shear-warp: at most this many intermediate-image pixels a voxel where the "
                 "picture is finer, 1 (Lacroute's one a voxel) to 4 (default 2)")
      ->check(CLI::Range(1.0, 4.0));
  app.add_option("--tf", o->tfFile, "Transfer function JSON file");
  std::vector<std::string> presetKeys;
  for (const TransferFunctionPresetInfo& p : transferFunctionPresets()) presetKeys.push_back(p.key);
  app.add_option("--tf-preset", o->tfPresets,
                 "Apply a preset to the transfer function (--tf's, the sidecar's or the "
                 "histogram's): ct-bone, ct-soft-tissue, mr, grayscale-ramp replace it; the colour "
                 "maps viridis, inferno, cool-to-warm, rainbow recolour it (repeat: in order)")
      ->check(CLI::IsMember(presetKeys))
      ->expected(1)  // one a time, so a file named after it is not taken for a preset
      ->allow_extra_args(false)
      ->take_all();
  app.add_option("--background", bg, "Background colour R,G,B in [0,1] (default 0,0,0)")
      ->delimiter(',')
      ->expected(3)
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--backend", o->backend,
                 "Headless OpenGL: osmesa (default; EWAVIEW_BACKEND names another) or egl")
      ->check(CLI::IsMember({"osmesa", "egl"}));
  app.add_option("--shader-dir", o->shaderDir, "Load shaders from this folder (development)");
  auto* rawDims = app.add_option("--raw-dims", o->rawDims, "Raw input: dims X,Y,Z");
  app.add_option(
         "--raw-type", o->rawType,
         "Raw input: int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32 or float64")
      ->needs(rawDims);
  app.add_option("--raw-spacing", o->rawSpacing, "Raw input: spacing X,Y,Z (default 1,1,1)")
      ->needs(rawDims);
  app.add_option("--raw-endian", o->rawEndian, "Raw input: little (default) or big")
      ->needs(rawDims);
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
  if (allowOutsideData) o->load.dataFiles = DataFileScope::Anywhere;
  o->cameraPosition = toVec3(pos);
  o->cameraFocalPoint = toVec3(focal);
  o->cameraViewUp = toVec3(up);
  if (!bg.empty()) o->render.background = glm::dvec3(bg[0], bg[1], bg[2]);
  parseFilterMode(filter, &o->render.filter);
  parseRenderMode(mode, &o->render.mode);
  if (closeUp) applyCloseUp(app, &renderText, &o->render);
  if (const std::string e = finishShadingOptions(renderText, &o->render); !e.empty())
    return usage(e);
  if (const std::string e = finishClipOptions(clipText, &o->render.clip); !e.empty())
    return usage(e);
  if (o->tour > 0 && o->render.clip.active())
    return usage(
        "--tour takes the crop box and planes of its bookmarks: leave --crop and "
        "--clip-plane out");
  if (!o->saveVolume.empty() && !o->render.clip.planes.empty())
    return usage(
        "--save-volume cuts the volume to --crop's box; a clipping plane cannot cut a grid: "
        "leave --clip-plane out");
  if (lowPassText != "auto") o->render.lowPass = std::stod(lowPassText);  // checked above
  parseRendererKind(rendererName, &o->render.renderer);
  parseTableLookup(lookup, &o->render.shearWarp.lookup);
  parseBufferSlices(buffers, &o->render.shearWarp.buffers);
  o->render.shearWarp.opacityCorrection = correction == "on";
  return {true, 0};
}

}  // namespace ewa
