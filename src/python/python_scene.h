// PythonScene: what `ewaview.Scene` holds: a volume, its transfer function, options, a renderer.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "app/headless_session.h"
#include "app/options.h"
#include "app/scene.h"
#include "app/scene_render.h"
#include "core/camera_tour.h"
#include "core/transfer_function.h"
#include "core/volume.h"

namespace ewa::python {

class PythonScene {
 public:
  // From a file (any loader ewaview has) or options alone (synthetic=...); `options` are
  // command-line options in Python form, load options (tf, raw_*, synthetic) included.
  PythonScene(const std::string& path, const pybind11::dict& options);
  // From an array indexed [z, y, x] (x varies fastest, as in VTK), with world spacing and
  // origin; uint8, int16, uint16 and float32 are kept, float64 becomes float32.
  PythonScene(const pybind11::array& data, const pybind11::object& spacing,
              const pybind11::object& origin, const pybind11::dict& options);

  // Adds render options (checked now, with the command line's messages).
  void set(const pybind11::dict& options);
  pybind11::dict options() const;

  // A preset name (ewaview.presets()) applied over the volume's value range, or the --tf JSON
  // structure as a dict; with channel="all", of channel `channel` (IndexError out of range).
  void setTransferFunction(const pybind11::object& tf, int channel = 0);
  pybind11::object transferFunction() const;
  // Every channel's transfer function with channel="all" (one entry otherwise).
  pybind11::list transferFunctions() const;

  // The picture as the command line draws it for these options: uint8 (H, W, 3).
  pybind11::array_t<uint8_t> render(const pybind11::dict& overrides);
  // `frames` pictures over 360 degrees about view-up, written as --turntable writes them to
  // `path` (a .mp4/.webm video at `fps`, a %d pattern or a folder).
  void turntable(const std::string& path, int frames, int fps, const pybind11::dict& overrides);
  // `frames` pictures through the camera bookmarks, as --tour writes them (`bookmarks`: a
  // NAME.bookmarks.json file; "": the one beside the scene's volume file).
  void tour(const std::string& path, int frames, int fps, const std::string& bookmarks,
            const pybind11::dict& overrides);
  // The same picture as PNG bytes, for Jupyter.
  pybind11::bytes png(const pybind11::dict& overrides);
  pybind11::dict info() const;
  // What pixel (x, y) of render(**overrides)'s picture shows, as --pick prints it, as a dict.
  pybind11::dict pick(double x, double y, const pybind11::dict& overrides);
  // The voxels as loaded (scaled and flipped as the renderers see them), a new [z, y, x] array
  // of the volume's type.
  pybind11::array array() const;
  std::string repr() const;
  // --save-volume: the volume as a gzip NRRD file (a path not ending in .nrrd: ValueError).
  // `crop`: None, or a box as render()'s crop= takes it: only its voxels are written.
  void saveVolume(const std::string& path, const pybind11::object& crop) const;

 private:
  Options renderOptions(const pybind11::dict& overrides);
  HeadlessSession& session(const Options& options);
  Image8 renderImage(const pybind11::dict& overrides);
  // `frames` pictures, frame f seen as `view(f)` says, written to `path` as a FrameSink.
  void writeFrames(const std::string& path, int frames, int fps, const Options& options,
                   const std::function<TourStop(int)>& view);

  // The volume and layers to draw: one, or with channel="all" every channel (scene_render.h).
  std::vector<RenderLayer> layers() const;

  std::shared_ptr<Volume> volume_;
  TransferFunction tf_;
  std::vector<SceneChannel> moreChannels_;  // channel="all": channels 1, 2, ...
  std::string name_;
  std::string file_;        // the volume's file ("" for arrays and synthetic volumes)
  pybind11::dict options_;  // render options in Python form, in the order given
  std::unique_ptr<HeadlessSession> session_;
  // Renders run without the GIL; this keeps one scene's renders and edits apart.
  std::mutex mutex_;
  std::string sessionBackend_, sessionShaders_;
};

// Names of the transfer-function presets, in menu order.
pybind11::list presetNames();
// Writes a uint8 (H, W, 3) or (H, W, 4) array as a PNG, atomically.
void writePngArray(const std::string& path, const pybind11::array& image);

}  // namespace ewa::python
