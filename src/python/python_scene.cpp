// PythonScene: loading (file, options or array), transfer functions, rendering through the
// command line's parser and HeadlessSession, so the pictures equal the command line's.
#include "python/python_scene.h"

#include <cmath>
#include <cstring>

#include "app/headless.h"
#include "app/pick_output.h"
#include "app/scene.h"
#include "app/turntable.h"
#include "core/camera_views.h"
#include "core/transfer_function_presets.h"
#include "io/frame_sink.h"
#include "io/png_io.h"
#include "io/transfer_function_io.h"
#include "io/viewer_settings.h"
#include "io/volume_writer.h"
#include "python/python_options.h"

namespace py = pybind11;

namespace ewa::python {

namespace {

// A note the command line says on stderr, as a Python UserWarning (an error when warnings are
// errors).
void warn(const std::string& note) {
  if (!note.empty() && PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0)
    throw py::error_already_set();
}

// A new dict with the same items (py::dict's copy constructor shares the object).
py::dict copyOf(const py::dict& d) {
  return py::reinterpret_steal<py::dict>(PyDict_Copy(d.ptr()));
}

py::object fromJson(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

// Splits `options` into the load options and the render options kept for later renders.
py::dict renderOptionsOf(const py::dict& options) {
  py::dict kept;
  for (const auto& [k, v] : options)
    if (!isLoadOption(py::str(k).cast<std::string>())) kept[k] = v;
  return kept;
}

glm::dvec3 vec3Argument(const py::object& value, glm::dvec3 fallback, const char* name) {
  if (value.is_none()) return fallback;
  std::vector<double> v;
  try {
    v = value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
  }
  if (v.size() != 3) throw UsageError(std::string(name) + ": needs three numbers X,Y,Z");
  return {v[0], v[1], v[2]};
}

template <typename T>
std::vector<uint8_t> contiguousBytes(const py::array& data) {
  const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(data);
  if (!a) throw UsageError("array: cannot be read as a contiguous array");
  std::vector<uint8_t> bytes(size_t(a.nbytes()));
  if (!bytes.empty()) std::memcpy(bytes.data(), a.data(), bytes.size());
  return bytes;
}

}  // namespace

PythonScene::PythonScene(const std::string& path, const py::dict& options) {
  std::vector<std::string> words = optionWords(options);
  if (!path.empty()) words.insert(words.begin(), path);
  const Options o = parseOptionWords(words);
  Scene scene = loadScene(o);
  volume_ = std::make_shared<Volume>(std::move(scene.volume));
  tf_ = std::move(scene.transferFunction);
  moreChannels_ = std::move(scene.moreChannels);
  name_ = scene.name;
  file_ = o.file;
  options_ = renderOptionsOf(options);
}

PythonScene::PythonScene(const py::array& data, const py::object& spacing, const py::object& origin,
                         const py::dict& options) {
  for (const auto& [k, v] : options) {
    const std::string key = py::str(k).cast<std::string>();
    if (key != "tf" && key != "tf_preset" && isLoadOption(key))
      throw UsageError(key + ": not with an array volume");
  }
  const Options o = parseOptionWords(optionWords(options));
  if (data.ndim() != 3)
    throw UsageError("array: needs 3 dimensions [z, y, x], got " + std::to_string(data.ndim()));
  const char kind = data.dtype().kind();
  const size_t size = size_t(data.itemsize());
  ScalarType type;
  std::vector<uint8_t> bytes;
  // As the loaders do: int8 widened to int16, the 32- and 64-bit types made float32.
  if (kind == 'u' && size == 1) {
    type = ScalarType::UInt8, bytes = contiguousBytes<uint8_t>(data);
  } else if (kind == 'i' && size <= 2) {
    type = ScalarType::Int16, bytes = contiguousBytes<int16_t>(data);
  } else if (kind == 'u' && size == 2) {
    type = ScalarType::UInt16, bytes = contiguousBytes<uint16_t>(data);
  } else if ((kind == 'f' || kind == 'i' || kind == 'u') && (size == 4 || size == 8)) {
    type = ScalarType::Float32, bytes = contiguousBytes<float>(data);
  } else {
    throw UsageError("array: dtype " + py::str(data.dtype()).cast<std::string>() +
                     " not supported (use integers, float32 or float64)");
  }
  const std::array<int64_t, 3> dims{int64_t(data.shape(2)), int64_t(data.shape(1)),
                                    int64_t(data.shape(0))};
  volume_ = std::make_shared<Volume>(dims, vec3Argument(spacing, glm::dvec3(1.0), "spacing"),
                                     vec3Argument(origin, glm::dvec3(0.0), "origin"), type,
                                     std::move(bytes));
  tf_ = withPresets(
      o.tfFile.empty() ? defaultTransferFunction(*volume_) : loadTransferFunction(o.tfFile),
      o.tfPresets, *volume_);
  name_ = "array";
  options_ = renderOptionsOf(options);
}

void PythonScene::set(const py::dict& options) {
  py::dict merged = copyOf(options_);
  for (const auto& [k, v] : options) {
    const std::string key = py::str(k).cast<std::string>();
    if (isLoadOption(key))
      throw UsageError(key + ": give it when the scene is made (or set transfer_function)");
    merged[k] = v;
  }
  parseOptionWords(optionWords(merged));  // checked now, so errors show where they are made
  options_ = merged;
}

py::dict PythonScene::options() const {
  return copyOf(options_);
}

void PythonScene::setTransferFunction(const py::object& tf, int channel) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (channel < 0 || size_t(channel) > moreChannels_.size())
    throw py::index_error("channel " + std::to_string(channel) + ": the scene draws " +
                          std::to_string(moreChannels_.size() + 1) + " channel(s)");
  TransferFunction& target =
      channel == 0 ? tf_ : moreChannels_[size_t(channel - 1)].transferFunction;
  const Volume& volume = channel == 0 ? *volume_ : moreChannels_[size_t(channel - 1)].volume;
  if (py::isinstance<py::str>(tf)) {
    target = applyTransferFunctionPreset(target, tf.cast<std::string>(), volume.minValue(),
                                         volume.maxValue());
  } else if (py::isinstance<py::dict>(tf)) {
    const std::string text = py::module_::import("json").attr("dumps")(tf).cast<std::string>();
    try {
      target = parseTransferFunctionJson(text, "transfer_function");
    } catch (const std::runtime_error& e) {
      throw UsageError(e.what());  // a bad argument here, where the command line has a bad file
    }
  } else {
    throw UsageError("transfer_function: give a preset name or a dict like the --tf JSON");
  }
}

py::object PythonScene::transferFunction() const {
  return fromJson(transferFunctionToJson(tf_));
}

py::list PythonScene::transferFunctions() const {
  py::list all;
  for (const RenderLayer& layer : layers())
    all.append(fromJson(transferFunctionToJson(*layer.transferFunction)));
  return all;
}

std::vector<RenderLayer> PythonScene::layers() const {
  std::vector<RenderLayer> out{{volume_.get(), &tf_}};
  for (const SceneChannel& c : moreChannels_) out.push_back({&c.volume, &c.transferFunction});
  return out;
}

Options PythonScene::renderOptions(const py::dict& overrides) {
  py::dict all = copyOf(options_);
  for (const auto& [k, v] : overrides) {
    if (isLoadOption(py::str(k).cast<std::string>()))
      throw UsageError(py::str(k).cast<std::string>() + ": give it when the scene is made");
    all[k] = v;
  }
  return parseOptionWords(optionWords(all));
}

HeadlessSession& PythonScene::session(const Options& o) {
  if (!session_ || o.backend != sessionBackend_ || o.shaderDir != sessionShaders_) {
    session_.reset();
    session_ = std::make_unique<HeadlessSession>(o.backend, o.shaderDir);
    sessionBackend_ = o.backend;
    sessionShaders_ = o.shaderDir;
  }
  return *session_;
}

Image8 PythonScene::renderImage(const py::dict& overrides) {
  const Options o = renderOptions(overrides);
  const Camera camera = initialCamera(*volume_, o);
  Image8 image;
  std::string note;
  {
    py::gil_scoped_release released;
    std::lock_guard<std::mutex> lock(mutex_);
    HeadlessSession& s = session(o);
    s.setAxes(o.axes);
    image = renderLayers(s, layers(), camera, o.render, o.width, o.height);
    note = s.takeNote();
  }
  warn(note);  // the renderer's own (RenderStats::note)
  return image;
}

void PythonScene::writeFrames(const std::string& path, int frames, int fps, const Options& o,
                              const std::function<TourStop(int)>& view) {
  std::string notes;
  {
    py::gil_scoped_release released;
    std::lock_guard<std::mutex> lock(mutex_);
    const std::unique_ptr<FrameSink> sink = openFrameSink(path, frames, fps);
    HeadlessSession& s = session(o);
    s.setAxes(o.axes);
    for (const std::string& note : renderViews(s, *sink, layers(), o, frames, view))
      notes += (notes.empty() ? "" : "; ") + note;
  }
  warn(notes);
}

void PythonScene::turntable(const std::string& path, int frames, int fps,
                            const py::dict& overrides) {
  const Options o = renderOptions(overrides);
  const Camera start = initialCamera(*volume_, o);
  writeFrames(path, frames, fps, o, [&](int f) {
    return TourStop{turntableCamera(start, f, frames), o.render.clip};
  });
}

void PythonScene::tour(const std::string& path, int frames, int fps, const std::string& bookmarks,
                       const py::dict& overrides) {
  const Options o = renderOptions(overrides);
  if (frames < 2) throw UsageError("tour: frames must be 2 or more");
  if (o.render.clip.active())
    throw UsageError(
        "tour: takes the crop box and planes of its bookmarks: leave crop and "
        "clip_planes out");
  const std::vector<TourStop> stops = loadTourStops(bookmarks, file_, name_, defaultConfigDir());
  writeFrames(path, frames, fps, o, [&](int f) { return tourFrame(stops, f, frames); });
}

py::array_t<uint8_t> PythonScene::render(const py::dict& overrides) {
  const Image8 img = renderImage(overrides);
  py::array_t<uint8_t> out({img.height, img.width, 3});
  uint8_t* dst = out.mutable_data();
  const size_t pixels = size_t(img.width) * img.height;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c) dst[p * 3 + c] = img.pixels[p * img.channels + c];
  return out;
}

py::bytes PythonScene::png(const py::dict& overrides) {
  const std::string bytes = encodePng(renderImage(overrides));
  return py::bytes(bytes);
}

py::dict PythonScene::pick(double x, double y, const py::dict& overrides) {
  Options o = renderOptions(overrides);
  if (!(x >= 0.0 && y >= 0.0 && x < o.width && y < o.height))
    throw UsageError("pick: pixel (" + py::str(py::float_(x)).cast<std::string>() + ", " +
                     py::str(py::float_(y)).cast<std::string>() + ") lies outside the " +
                     std::to_string(o.width) + "x" + std::to_string(o.height) + " picture");
  o.pick = glm::dvec2(x, y);
  return py::dict(fromJson(pickJson(*volume_, tf_, o)));
}

py::dict PythonScene::info() const {
  py::dict d = fromJson(volumeInfoJson(*volume_));
  d["name"] = name_;
  return d;
}

void PythonScene::saveVolume(const std::string& path, const py::object& crop) const {
  if (!savedVolumeFormat(path))
    throw UsageError("save_volume: " + path + ": the file must end in " +
                     savedVolumeExtensionsText());
  // What the format leaves out comes as Python warnings, as --save-volume's notes.
  auto write = [&](const Volume& v) {
    for (const std::string& loss : writeVolumeAndLosses(path, v, volume_->sourceFiles()))
      py::module_::import("warnings").attr("warn")(path + ": " + loss);
  };
  if (crop.is_none()) return write(*volume_);
  py::dict box;
  box["crop"] = crop;  // read as --crop reads it, with its messages
  const Options options = parseOptionWords(optionWords(box));
  std::optional<Volume> cropped;
  try {
    cropped = croppedForSaving(*volume_, options.render.clip, name_);
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());  // a box beside the volume: the argument is wrong
  }
  write(cropped ? *cropped : *volume_);
}

py::array PythonScene::array() const {
  const auto& d = volume_->dims();
  const std::vector<py::ssize_t> shape{py::ssize_t(d[2]), py::ssize_t(d[1]), py::ssize_t(d[0])};
  py::dtype dtype;
  switch (volume_->type()) {
    case ScalarType::UInt8:
      dtype = py::dtype::of<uint8_t>();
      break;
    case ScalarType::Int16:
      dtype = py::dtype::of<int16_t>();
      break;
    case ScalarType::UInt16:
      dtype = py::dtype::of<uint16_t>();
      break;
    case ScalarType::Float32:
      dtype = py::dtype::of<float>();
      break;
  }
  py::array out(dtype, shape);  // C order: x fastest, as the volume holds its voxels
  const std::vector<uint8_t>& bytes = volume_->bytes();
  if (!bytes.empty()) std::memcpy(out.mutable_data(), bytes.data(), bytes.size());
  return out;
}

std::string PythonScene::repr() const {
  const auto& d = volume_->dims();
  return "<ewaview.Scene " + name_ + " " + std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" +
         std::to_string(d[2]) + " " + scalarName(volume_->type()) + ">";
}

void writePngArray(const std::string& path, const py::array& image) {
  const auto a = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>::ensure(image);
  if (!a || a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4) || image.dtype().kind() != 'u' ||
      image.itemsize() != 1)
    throw UsageError(path + ": needs a uint8 array of shape (H, W, 3) or (H, W, 4)");
  Image8 img;
  img.height = int(a.shape(0));
  img.width = int(a.shape(1));
  img.channels = int(a.shape(2));
  img.pixels.assign(a.data(), a.data() + a.size());
  writePng(path, img);
}

py::list presetNames() {
  py::list names;
  for (const TransferFunctionPresetInfo& p : transferFunctionPresets()) names.append(p.name);
  return names;
}

}  // namespace ewa::python
