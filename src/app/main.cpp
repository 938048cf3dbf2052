// ewaview entry point: parse the command line, then --info, headless output or the window.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/headless.h"
#include "app/heap_tuning.h"
#include "app/one_line.h"
#include "app/options.h"
#include "app/pick_output.h"
#include "app/scene.h"
#include "app/turntable.h"
#include "app/window_config.h"
#include "io/archive_cache.h"
#include "io/volume_writer.h"
#include "ui/viewer.h"

namespace {

// The window: saved settings where the command line says nothing, and an opener for files
// chosen in the window (the same loaders and transfer-function rules as the command line).
int runWindow(ewa::Scene scene, const ewa::Options& options) {
  ewa::ViewerConfig config;
  const std::string clipKey =
      options.synthetic.empty()
          ? std::filesystem::absolute(options.file.empty() ? ewa::defaultVolumePath()
                                                           : options.file)
                .string()
          : "synthetic:" + scene.name;
  const ewa::Options o = ewa::windowConfig(options, clipKey, &config);
  config.camera = ewa::initialCamera(scene.volume, o);
  // Every file the window opens shares `o.archives` (set in main), so the last archive stays
  // unpacked while its frames and series are paged.
  config.opener = [base = o](const std::string& path, const ewa::LoadOptions& load) {
    ewa::Options fileOptions = base;
    // The command line's raw file, opened again with another spacing, keeps its raw options.
    std::error_code ec;
    const bool commandLineFile =
        !base.file.empty() && std::filesystem::equivalent(path, base.file, ec);
    if (!commandLineFile) fileOptions.rawDims.clear();
    fileOptions.file = path;
    fileOptions.synthetic.clear();
    fileOptions.tfFile.clear();  // --tf was for the first volume; others use their sidecar
    fileOptions.tfPresets.clear();
    fileOptions.load = load;  // so were --series, --frame, --channel and --spacing: the
                              // window's own
    // The window pages frames and channels, not pyramid levels or HDF5 datasets: the command
    // line's file keeps its --level and --dataset.
    if (commandLineFile) {
      fileOptions.load.level = base.load.level;
      fileOptions.load.dataset = base.load.dataset;
    }
    ewa::Scene s = ewa::loadScene(fileOptions);
    ewa::LoadedVolume loaded;
    loaded.spacing = load.spacing;
    loaded.volume = std::make_shared<ewa::Volume>(std::move(s.volume));
    loaded.tf = std::move(s.transferFunction);
    loaded.name = s.name;
    loaded.path = std::filesystem::absolute(path).string();
    return loaded;
  };
  ewa::LoadedVolume initial;
  initial.volume = std::make_shared<ewa::Volume>(std::move(scene.volume));
  initial.tf = std::move(scene.transferFunction);
  initial.name = scene.name;
  initial.spacing = o.load.spacing;
  if (options.synthetic.empty())
    initial.path =
        std::filesystem::absolute(options.file.empty() ? ewa::defaultVolumePath() : options.file)
            .string();
  return ewa::runViewer(std::move(initial), config);
}

}  // namespace

int main(int argc, char** argv) {
  ewa::Options options;
  const ewa::ParseResult parsed = ewa::parseCommandLine(argc, argv, &options);
  if (!parsed.run) return parsed.exitCode;
  // Python's scenes overlay channels too; of this program's ways only the window does not.
  if (options.overlay && options.output.empty()) {
    std::cerr << "ewaview: --channel all (or a list) draws headless only (with --output, "
                 "--turntable or --tour); the window shows one channel at a time (C pages "
                 "through them)\n";
    return 2;
  }
  ewa::askForHugePages(argv);  // returns here only without it; else main runs again
  ewa::keepFreedHeapForReuse();
  // A window keeps an archive it opens unpacked (ArchiveCache), from the first volume on.
  if (options.output.empty() && !options.info && !options.pick && options.turntable == 0 &&
      options.tour == 0 && options.saveVolume.empty())
    options.archives = std::make_shared<ewa::ArchiveCache>();
  try {
    ewa::Scene scene = ewa::loadScene(options);
    if (!options.saveVolume.empty()) {
      // With --crop, the box's voxels only; --info then describes what was written. The files
      // read are kept from replacement whatever is written.
      const std::vector<std::string> inputs = ewa::sceneInputFiles(scene, options);
      if (auto cropped = ewa::croppedForSaving(scene.volume, options.render.clip,
                                               options.file.empty() ? scene.name : options.file))
        scene.volume = std::move(*cropped);
      for (const std::string& loss :
           ewa::writeVolumeAndLosses(options.saveVolume, scene.volume, inputs))
        std::cerr << "ewaview: note: " << options.saveVolume << ": " << loss << "\n";
      if (!options.info) return 0;
    }
    if (options.info) {
      std::cout << ewa::volumeInfoJson(scene.volume) << "\n";
      return 0;
    }
    if (options.pick) {
      std::cout << ewa::pickJson(scene.volume, scene.transferFunction, options) << "\n";
      return 0;
    }
    if (options.turntable > 0) {
      ewa::renderTurntable(scene, options);
      return 0;
    }
    if (options.tour > 0) {
      ewa::renderTour(scene, options);
      return 0;
    }
    if (!options.output.empty()) {
      ewa::renderHeadless(scene, options);
      return 0;
    }
    return runWindow(std::move(scene), options);
  } catch (const std::exception& e) {
    std::cerr << "ewaview: " << ewa::oneLine(e.what()) << "\n";
    return 1;
  }
}
