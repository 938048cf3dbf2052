// ViewerWindow's volumes: opening and saving files on worker threads, adopting a loaded volume, the
// renderers of the chosen kind and the full level's splat sets built elsewhere.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "core/camera_views.h"
#include "io/file_listing.h"
#include "io/frame_names.h"
#include "io/volume_writer.h"
#include "render/renderer_factory.h"
#include "ui/viewer_window.h"

namespace ewa {

namespace {

// The series the open volume is (so that paging keeps to it), or "" for the file's default.
std::string openSeriesId(const Volume& v) {
  for (const SeriesChoice& c : v.seriesChoices())
    if (c.open) return c.id;
  return {};
}

}  // namespace

void ViewerWindow::info(const std::string& text) {
  messages_.post(StatusMessages::Kind::Info, text, now());
  std::cerr << "ewaview: " << text << "\n";
}

void ViewerWindow::error(const std::string& text) {
  messages_.post(StatusMessages::Kind::Error, text, now());
  std::cerr << "ewaview: " << text << "\n";
}

// Makes `loaded` the volume on screen (the old one stays alive until the renderers let go).
void ViewerWindow::adopt(LoadedVolume loaded, bool newCamera) {
  liveTf_.dropBuild();  // a build may still read the old volume
  refinement_.cancel();
  LoadedVolume old = std::move(current_);
  current_ = std::move(loaded);
  probe_.setMark(std::nullopt);  // a point of the old volume
  lod_.setVolume(*current_.volume, current_.coarse);
  lod_.setTransferFunction(current_.tf);
  policy_.setCoarsestLevel(lod_.coarsestLevel());
  policy_.resetMeasurements();
  panel_.setVolume(current_.name, *current_.volume, !current_.path.empty());
  liveTf_.reset(
      *current_.volume, current_.tf,
      saved_.lastTransferFunction.empty() ? "transfer_function.json" : saved_.lastTransferFunction,
      printLayout_);
  if (newCamera) {
    settings_.clip = ClipRegion{};  // a box and planes in another volume's coordinates
    ++settingsRevision_;
    const glm::ivec2 fb = window_.framebufferSize();
    Camera camera;
    camera.viewAngleDeg = controller_.camera().viewAngleDeg;
    camera.orthographic = controller_.camera().orthographic;
    camera = initialVolumeView(
        camera, current_.volume->worldBoundsMin(), current_.volume->worldBoundsMax(),
        fb.y > 0 ? double(fb.x) / fb.y : 1.0, current_.volume->patientFrame());
    controller_.restart(camera);
  }
  if (!current_.path.empty()) addRecentFile(saved_.recentFiles, current_.path);
  fileWatch_.watch(current_.path);  // what is on screen now; a later change reloads it
  const std::string problem = bookmarks_.open(current_.path, current_.name, config_.configDir);
  if (!problem.empty()) error(problem);
  hasImage_ = false;
  fullLevelAsked_ = false;
  buildPending_ = true;  // one frame says so before the first (slow) render classifies
}

bool ViewerWindow::startLoad(const std::string& path, const LoadOptions& load, bool keepView) {
  if (!config_.fixedVolume.empty()) {
    error(config_.fixedVolume);
    return false;
  }
  if (loadJob_.running()) {
    error("still loading " + loadJob_.path() + "; try again when it is done");
    return false;
  }
  std::cerr << "ewaview: loading " << path << (load.series.empty() ? "" : " series " + load.series)
            << (load.frame > 0 ? " frame " + std::to_string(load.frame) : "")
            << (load.channel > 0 ? " channel " + std::to_string(load.channel) : "") << "\n";
  loadKeepsView_ = keepView;
  loadKeepsTf_ = false;
  loadIsReload_ = false;
  loadJob_.start(path, load, config_.opener);
  return true;
}

void ViewerWindow::reload() {
  if (current_.path.empty()) {
    info(current_.name + " is made here, not read from a file: nothing to reload");
    return;
  }
  if (loadJob_.running()) return;  // the file is being read already
  if (startLoad(current_.path, pageBase(), true)) loadKeepsTf_ = loadIsReload_ = true;
}

// The file opened again with another voxel spacing (the panel's "Set spacing"): the same page
// and transfer function, framed anew (the volume's shape changed).
void ViewerWindow::respace(const glm::dvec3& spacing) {
  if (current_.path.empty()) return;
  LoadOptions load = pageBase();
  load.spacing = spacing;
  if (startLoad(current_.path, load)) loadKeepsTf_ = true;
}

// Paging steps from the frame and channel last asked for while a page is loading (a held
// Page Down goes on counting), else from the volume on screen.
LoadOptions ViewerWindow::pageBase() const {
  if (loadJob_.running() && loadKeepsView_) return pageTarget_;
  LoadOptions load;
  load.series = openSeriesId(*current_.volume);
  load.frame = current_.volume->frame();
  load.channel = current_.volume->channel();
  load.spacing = current_.spacing;
  return load;
}

// Opens that page of the current file now, or, while another page loads, right after it (the
// latest request replacing any queued one), so no key press is refused.
void ViewerWindow::requestPage(const LoadOptions& load) {
  pageTarget_ = load;
  if (loadJob_.running() && loadKeepsView_)
    queuedPage_ = load;
  else
    startLoad(current_.path, load, true);
}

// Steps `which` (the frame or the channel) of the page by `step`, round the `count` there are.
void ViewerWindow::stepPage(int LoadOptions::*which, int count, int step) {
  if (count <= 1 || current_.path.empty()) return;
  LoadOptions load = pageBase();
  load.*which = ((load.*which + step) % count + count) % count;
  requestPage(load);
}

void ViewerWindow::stepFrame(int step) {
  stepPage(&LoadOptions::frame, current_.volume->frameCount(), step);
}

void ViewerWindow::stepChannel(int step) {
  stepPage(&LoadOptions::channel, current_.volume->channelCount(), step);
}

void ViewerWindow::openSeries(const std::string& id) {
  if (current_.path.empty() || id == openSeriesId(*current_.volume)) return;
  LoadOptions load;
  load.series = id;
  startLoad(current_.path, load);
}

void ViewerWindow::pollLoad() {
  std::optional<LoadedVolume> loaded;
  std::string problem;
  const double seconds = loadJob_.elapsedSeconds();
  if (!loadJob_.poll(&loaded, &problem)) return;
  if (!loaded) {
    error(problem);  // the old volume stays
    queuedPage_.reset();
    return;
  }
  char text[64];
  std::snprintf(text, sizeof text, " in %.1f s", seconds);
  const Volume& v = *loaded->volume;
  const bool sameGrid = current_.volume && v.dims() == current_.volume->dims() &&
                        v.spacing() == current_.volume->spacing();
  const bool keepView = loadKeepsView_ && sameGrid;  // else a new volume after all
  if (keepView && loadIsReload_) {
    info("reloaded " + loaded->name + text);
    loaded->tf = current_.tf;  // the function being edited stays
  } else if (keepView) {
    info((v.channelCount() > 1 ? "channel " + std::to_string(v.channel()) + " of " +
                                     std::to_string(v.channelCount()) + ", "
                               : std::string()) +
         "frame " + std::to_string(v.frame()) + " of " + std::to_string(v.frameCount()) + text);
    // Another frame keeps the function being edited. Another channel (another stain, another
    // range) gets its own: the one it had when last shown, else the file's for that channel.
    const int was = current_.volume->channel();
    channelTfs_[was] = current_.tf;
    const auto kept = channelTfs_.find(v.channel());
    if (v.channel() == was)
      loaded->tf = current_.tf;
    else if (kept != channelTfs_.end())
      loaded->tf = kept->second;
  } else if (loadKeepsTf_) {
    char spacing[96];
    std::snprintf(spacing, sizeof spacing, "spacing %g %g %g", v.spacing().x, v.spacing().y,
                  v.spacing().z);
    info(std::string(spacing) + text);
    loaded->tf = current_.tf;  // the same data: the function being edited stays
  } else {
    info("opened " + loaded->name + text);
    channelTfs_.clear();  // another file
  }
  // Uneven slices, a sheared grid: on stderr already (loadScene), and in the panel.
  for (const std::string& note : v.notes())
    if (note.rfind("warning: ", 0) == 0) messages_.post(StatusMessages::Kind::Info, note, now());
  adopt(std::move(*loaded), /*newCamera=*/!keepView);
  if (queuedPage_) {  // a page asked for while this one loaded, unless it is this one again
    const LoadOptions next = *queuedPage_;
    queuedPage_.reset();
    const Volume& now = *current_.volume;
    if (next.frame != now.frame() || next.channel != now.channel() ||
        next.series != openSeriesId(now))
      startLoad(current_.path, next, true);
  }
}

// Every level's renderer is of the kind settings_.renderer names (the panel switches it).
LodRenderer::Factory ViewerWindow::rendererFactory() {
  rendererKind_ = settings_.renderer;
  return [this] { return makeRenderer(); };
}

std::unique_ptr<Renderer> ViewerWindow::makeRenderer() {
  if (config_.rendererFactory) return config_.rendererFactory(window_);
  return createRenderer(settings_.renderer, shaders_, &splatPrograms_);
}

// A new set of renderers when the panel switched the renderer kind.
void ViewerWindow::switchRendererIfAsked() {
  if (settings_.renderer == rendererKind_) return;
  if (config_.rendererFactory) {  // its renderers draw splats whatever the kind
    settings_.renderer = rendererKind_;
    error("only the splat renderer is drawn here");
    return;
  }
  liveTf_.dropBuild();
  lod_ = LodRenderer(rendererFactory(), uploadContext_.get());
  lod_.setVolume(*current_.volume, current_.coarse);
  lod_.setTransferFunction(current_.tf);
  policy_.setCoarsestLevel(lod_.coarsestLevel());
  policy_.resetMeasurements();
  refinement_.cancel();
  hasImage_ = false;
  fullLevelAsked_ = false;
}

// Swaps in a splat set the worker finished; true when one arrived. Full quality on screen, or
// being refined, is refined again with it (the old picture stays until then); a coarse
// picture refines later anyway.
bool ViewerWindow::takeBuiltSplats() {
  std::string problem;
  if (!liveTf_.takeBuilt(lod_, &problem)) return false;
  if (!problem.empty())
    error(problem + " (the window keeps running)");
  else
    fullSplatsArrived_ = hasImage_ && (lod_.lastLevel() == 0 || refinement_.active());
  splatsUploaded_ = problem.empty();
  return true;
}

void ViewerWindow::openDialog() {
  const std::string folder =
      current_.path.empty() ? "" : std::filesystem::path(current_.path).parent_path().string();
  fileDialog_.open(folder);
}

// Offered as NAME.nrrd (NAME-fF-cC.nrrd for a page of a file of several; NAME-2.nrrd... when
// taken) in the file's folder; a NIfTI file's as NAME.nii.gz, a MetaImage file's as NAME.mha
// and a TIFF file's or a folder of TIFF slices' as NAME.tif, the format its users have.
void ViewerWindow::saveDialog() {
  namespace fs = std::filesystem;
  if (!config_.fixedVolume.empty()) {
    error(config_.fixedVolume);
    return;
  }
  const Volume& v = *current_.volume;
  std::string name =
      current_.path.empty() ? current_.name : fs::path(current_.path).stem().string();
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".nii") == 0)
    name.resize(name.size() - 4);
  auto format = savedVolumeFormat(current_.path);
  std::error_code ec;
  if (!format && fs::is_directory(current_.path, ec)) {  // a folder of TIFF slices: one stack
    try {
      if (!sliceFilesIn(current_.path, {".tif", ".tiff"}).empty()) format = SavedVolumeFormat::Tiff;
    } catch (const std::exception&) {
      // An unreadable folder: NRRD.
    }
  }
  const std::string extension = savedVolumeExtension(format.value_or(SavedVolumeFormat::Nrrd));
  if (v.frameCount() > 1) name += "-f" + std::to_string(v.frame());
  if (v.channelCount() > 1) name += "-c" + std::to_string(v.channel());
  for (char& c : name)
    if (c == ':' || c == '/') c = '_';  // a synthetic volume's "sphere:64"
  const std::string folder =
      current_.path.empty() ? "" : fs::path(current_.path).parent_path().string();
  // With a crop box on, the dialog offers to write only its voxels (ticked at first).
  saveCrop_.reset();
  if (settings_.clip.cropEnabled)
    saveCrop_ = voxelsInBox(v, settings_.clip.cropMin, settings_.clip.cropMax);
  std::string option;
  if (saveCrop_) {
    const auto d = saveCrop_->dims();
    option = "only the crop box (" + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
             std::to_string(d[2]) + " voxels)";
  }
  // Never the file on screen or another already there: NAME-2.nrrd, NAME-3.nrrd... as
  // screenshots are named.
  const std::string file = fs::path(unusedFileName(folder, name, extension)).filename().string();
  fileDialog_.open(folder, FileDialog::Purpose::SaveVolume, file, option);
}

void ViewerWindow::startSave(const std::string& path) {
  if (saveJob_.running()) {
    error("still saving " + saveJob_.path() + "; try again when it is done");
    return;
  }
  std::cerr << "ewaview: saving " << path << "\n";
  saveJob_.start(current_.volume, current_.tf, path,
                 fileDialog_.optionChecked() ? saveCrop_ : std::nullopt);
}

void ViewerWindow::pollSave() {
  std::string text;
  bool failed = false;
  if (!saveJob_.poll(&text, &failed)) return;
  if (failed)
    error(text);
  else
    info(text);
}

}  // namespace ewa
