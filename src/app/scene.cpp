// Scene loading, the default camera and the --info description.
#include "app/scene.h"

#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/camera_views.h"
#include "core/channel_overlay.h"
#include "core/synthetic_volume.h"
#include "core/transfer_function_presets.h"
#include "core/volume_crop.h"
#include "io/transfer_function_io.h"
#include "io/volume_loader.h"

namespace ewa {

std::string defaultVolumePath() {
  // Beside the executable's source tree when built; an installed copy would set this too.
  return std::string(EWA_ASSET_DIR) + "/default.nrrd";
}

namespace {

// --channel all (or a list): the file's other channels beside the one loaded first, and every
// channel's transfer function: its sidecar, else the histogram's in the channel's colour.
void loadMoreChannels(const Options& o, const std::string& sidecar0, Scene& scene) {
  const int count = scene.volume.channelCount();
  if (count <= 1 && o.overlayChannels.empty()) return;  // one channel: drawn as it is
  const std::string path = o.file.empty() ? defaultVolumePath() : o.file;
  std::vector<int> channels = o.overlayChannels;  // the first is scene.volume's
  if (channels.empty())
    for (int c = 0; c < count; ++c) channels.push_back(c);
  if (int(channels.size()) > kMaxOverlaidChannels)
    throw std::runtime_error(path + ": " + std::to_string(channels.size()) +
                             " channels; --channel overlays " +
                             std::to_string(kMaxOverlaidChannels) + " at most");
  const auto channelTf = [&](const Volume& volume, int c, const std::string& sidecar) {
    TransferFunction tf =
        std::filesystem::is_regular_file(sidecar)
            ? loadTransferFunction(sidecar)
            : inChannelColor(defaultTransferFunction(volume), channelColor(c, count));
    return withPresets(std::move(tf), o.tfPresets, volume);
  };
  if (!std::filesystem::is_regular_file(sidecar0))
    scene.transferFunction = channelTf(scene.volume, channels.front(), sidecar0);
  for (size_t n = 1; n < channels.size(); ++n) {
    const int c = channels[n];
    LoadOptions load = o.load;
    load.channel = c;
    SceneChannel channel{loadVolume(path, load, o.archives.get()), {}};
    channel.transferFunction = channelTf(channel.volume, c, sidecarTransferFunctionPath(path, c));
    scene.moreChannels.push_back(std::move(channel));
  }
}

}  // namespace

Scene loadScene(const Options& o) {
  Scene scene;
  std::optional<TransferFunction> ownTf;
  std::string sidecar;
  if (!o.synthetic.empty()) {
    SyntheticVolume s = makeSyntheticVolume(o.synthetic);
    scene.volume = std::move(s.volume);
    ownTf = s.transferFunction;
    scene.name = o.synthetic;
  } else {
    const std::string path = o.file.empty() ? defaultVolumePath() : o.file;
    if (o.rawDims.empty()) {
      scene.volume = loadVolume(path, o.load, o.archives.get());
    } else {
      scene.volume =
          loadRawVolume(path, parseRawOptions(o.rawDims, o.rawType, o.rawSpacing, o.rawEndian));
      if (o.load.spacing) overrideSpacing(path, scene.volume, *o.load.spacing);
    }
    scene.name = std::filesystem::path(path).filename().string();
    sidecar = sidecarTransferFunctionPath(path, o.load.channel);
    // Warnings (uneven slices, a sheared grid) are worth a line even when the load succeeds.
    for (const std::string& note : scene.volume.notes())
      if (note.compare(0, 9, "warning: ") == 0)
        std::cerr << "ewaview: " << path << ": " << note << "\n";
  }
  scene.transferFunction = sceneTransferFunction(o, sidecar, ownTf, scene.volume);
  if (o.overlay) loadMoreChannels(o, sidecar, scene);
  return scene;
}

TransferFunction sceneTransferFunction(const Options& o, const std::string& sidecar,
                                       const std::optional<TransferFunction>& own,
                                       const Volume& volume) {
  TransferFunction tf;
  if (!o.tfFile.empty()) {
    tf = loadTransferFunction(o.tfFile);
  } else if (!sidecar.empty() && std::filesystem::is_regular_file(sidecar)) {
    tf = loadTransferFunction(sidecar);
  } else if (own) {
    tf = *own;
  } else {
    tf = defaultTransferFunction(volume);
  }
  return withPresets(std::move(tf), o.tfPresets, volume);
}

TransferFunction withPresets(TransferFunction tf, const std::vector<std::string>& keys,
                             const Volume& volume) {
  for (const std::string& key : keys)
    tf = applyTransferFunctionPreset(tf, key, volume.minValue(), volume.maxValue());
  return tf;
}

Camera initialCamera(const Volume& volume, const Options& o) {
  return initialCameraForBounds(volume.worldBoundsMin(), volume.worldBoundsMax(),
                                volume.patientFrame(), o);
}

Camera initialCameraForBounds(const glm::dvec3& worldMin, const glm::dvec3& worldMax,
                              bool patientFrame, const Options& o) {
  Camera cam;
  cam.viewAngleDeg = o.cameraViewAngle;
  cam.orthographic = o.orthographic;
  // VTK's default view (from +z, y up), or the anterior view of a patient; in world space.
  cam =
      initialVolumeView(cam, worldMin, worldMax, double(o.width) / double(o.height), patientFrame);
  if (o.cameraFocalPoint) cam.focalPoint = *o.cameraFocalPoint;
  if (o.cameraPosition) cam.position = *o.cameraPosition;
  if (o.cameraViewUp) cam.viewUp = *o.cameraViewUp;
  if (!cam.valid())
    throw std::runtime_error(
        "camera: position and focal point must differ and view-up be non-zero");
  return cam;
}

std::optional<Volume> croppedForSaving(const Volume& volume, const ClipRegion& clip,
                                       const std::string& name) {
  if (!clip.cropEnabled) return std::nullopt;
  const std::optional<VoxelRange> range = voxelsInBox(volume, clip.cropMin, clip.cropMax);
  if (!range) {
    const glm::dvec3 lo = volume.worldBoundsMin(), hi = volume.worldBoundsMax();
    char bounds[160];
    std::snprintf(bounds, sizeof bounds, "%g,%g,%g,%g,%g,%g", lo.x, hi.x, lo.y, hi.y, lo.z, hi.z);
    throw std::runtime_error(
        name + ": the crop box keeps no voxel of the volume (its centres lie in " + bounds + ")");
  }
  return cropVolume(volume, *range);
}

std::string volumeInfoJson(const Volume& v) {
  nlohmann::ordered_json j;  // keeps the documented key order
  j["dims"] = {v.dims()[0], v.dims()[1], v.dims()[2]};
  j["spacing"] = {v.spacing().x, v.spacing().y, v.spacing().z};
  j["type"] = scalarName(v.type());
  j["range"] = {v.minValue(), v.maxValue()};
  j["origin"] = {v.origin().x, v.origin().y, v.origin().z};
  // Rows of D: column a is the world direction of data axis a.
  const glm::dmat3& d = v.direction();
  j["direction"] = {
      {d[0][0], d[1][0], d[2][0]}, {d[0][1], d[1][1], d[2][1]}, {d[0][2], d[1][2], d[2][2]}};
  j["space"] = v.patientFrame() ? "LPS" : "none";  // patient axes, or none
  // The unit of spacing, origin and world lengths; null when the file does not say.
  j["unit"] = v.unit().empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(v.unit());
  j["frame"] = v.frame();  // of frames: the file's volumes (--frame)
  j["frames"] = v.frameCount();
  j["channel"] = v.channel();  // of channels (--channel)
  j["channels"] = v.channelCount();
  // A DICOM folder's series (--series ID opens one); empty for a folder of one, other formats.
  j["series"] = nlohmann::ordered_json::array();
  for (const SeriesChoice& c : v.seriesChoices())
    j["series"].push_back({{"id", c.id}, {"label", c.label}, {"open", c.open}});
  j["notes"] = v.notes();
  return j.dump();
}

}  // namespace ewa
