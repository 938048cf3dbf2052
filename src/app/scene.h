// Scene: the volume, transfer function and starting camera that the options describe.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "core/camera.h"
#include "core/clip_region.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "io/transfer_function_io.h"  // sidecarTransferFunctionPath

namespace ewa {

// One more channel of a file shown with --channel all, and the transfer function it is drawn with.
struct SceneChannel {
  Volume volume;
  TransferFunction transferFunction;
};

struct Scene {
  Volume volume;  // with --channel all, channel 0
  TransferFunction transferFunction;
  std::string name;
  std::vector<SceneChannel> moreChannels;  // --channel all: channels 1, 2, ...
};

// The most channels --channel all overlays (each a volume and a renderer of its own).
constexpr int kMaxOverlaidChannels = 16;

// Path of the volume opened when no FILE or --synthetic is given.
std::string defaultVolumePath();

// Loads the volume (file, raw or synthetic) and the transfer function: --tf, else a sidecar
// file beside the volume, else the synthetic volume's own, else one made from the histogram. Throws
// std::runtime_error("<file>: problem"). With --channel all (and a file of several channels),
// every channel, each with its sidecar (NAME.tf.json, NAME.cC.tf.json) or else the
// histogram's function in the channel's colour (channelColor); at most kMaxOverlaidChannels.
Scene loadScene(const Options& options);

// `tf` with the --tf-preset keys applied in order, over the volume's value range.
TransferFunction withPresets(TransferFunction tf, const std::vector<std::string>& keys,
                             const Volume& volume);

// The starting camera: framing the volume from the front, then any --camera-* options.
Camera initialCamera(const Volume& volume, const Options& options);
// The same for a volume known by its world bounds and frame alone (a distributed run, where no
// process holds the whole volume).
Camera initialCameraForBounds(const glm::dvec3& worldMin, const glm::dvec3& worldMax,
                              bool patientFrame, const Options& options);

// The transfer function loadScene gives `volume` (its value range and histogram): --tf, else
// the file's sidecar (`sidecar`, "" for none), else the synthetic volume's own (`own`), else
// the default; with --tf-preset's presets applied.
TransferFunction sceneTransferFunction(const Options& options, const std::string& sidecar,
                                       const std::optional<TransferFunction>& own,
                                       const Volume& volume);

// The volume --save-volume (and Python's save_volume) writes: `volume` cut to the crop box
// when `clip` has one (cropVolume), else nothing (the volume as it is). Throws
// std::runtime_error("<name>: the crop box keeps no voxel ...") when the box misses every voxel.
std::optional<Volume> croppedForSaving(const Volume& volume, const ClipRegion& clip,
                                       const std::string& name);

// --info: {"dims":[x,y,z],"spacing":[x,y,z],"type":"uint8","range":[lo,hi]}.
std::string volumeInfoJson(const Volume& volume);

}  // namespace ewa
