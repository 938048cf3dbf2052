// The Python module `ewaview` (pybind11): scenes from files or NumPy arrays, rendered headless.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include "app/one_line.h"
#include "app/version.h"
#include "python/python_options.h"
#include "python/python_scene.h"

namespace py = pybind11;
using ewa::python::PythonScene;

PYBIND11_MODULE(ewaview, m) {
  m.doc() =
      "ewaview: EWA volume splatting (and CPU shear-warp) rendered headless to NumPy arrays.\n\n"
      "    scene = ewaview.Scene('engine.nrrd', resolution=(512, 512))\n"
      "    scene.transfer_function = 'CT bone'\n"
      "    image = scene.render(renderer='shearwarp', shading=True)  # uint8 (H, W, 3)\n\n"
      "Options are the command line's, with '_' for '-': render_mode='mip' is --render-mode mip,\n"
      "True is a flag, sequences are X,Y,Z.";
  m.attr("__version__") = ewa::versionString();
  // Errors carry the command line's one-line messages: usage -> ValueError, others RuntimeError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const py::builtin_exception& e) {
      e.set_error();  // IndexError and the like as pybind11 raises them
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, ewa::oneLine(e.what()).c_str());
    } catch (const std::exception& e) {
      PyErr_SetString(PyExc_RuntimeError, ewa::oneLine(e.what()).c_str());
    }
  });
  m.def("presets", &ewa::python::presetNames, "Names of the transfer-function presets.");
  m.def(
      "write_png",
      [](const std::filesystem::path& path, const py::array& image) {
        ewa::python::writePngArray(path.string(), image);
      },
      py::arg("path"), py::arg("image"),
      "Writes a uint8 (H, W, 3) or (H, W, 4) array as a PNG file (atomically).");

  py::class_<PythonScene>(m, "Scene", R"(A volume, its transfer function and render options.

Scene(path=None, spacing=None, **options): a volume file or folder ewaview reads (.nrrd .nhdr
.mhd .mha .dat .vti .nii .dcm .tif .png ..., raw with raw_dims=..., raw_type=...), or
synthetic='sphere:64'; no path: the default volume. spacing=(sx, sy, sz) replaces the file's.
Scene(array, spacing=(1, 1, 1), origin=(0, 0, 0), **options): a NumPy array indexed [z, y, x]
(uint8, int16, uint16, float32 as they are; int8 becomes int16, 32- and 64-bit
integers and float64 become float32).
The transfer function is tf=FILE's, else a FILE.tf.json beside the volume, else one made from
the histogram, as on the command line. channel='all' overlays every channel of a file as
--channel all does, each with its own transfer function (set_transfer_function(tf, channel)).)")
      .def(py::init([](py::object source, py::object spacing, py::object origin,
                       py::kwargs options) {
             if (py::isinstance<py::array>(source))
               return std::make_unique<PythonScene>(source.cast<py::array>(), spacing, origin,
                                                    options);
             if (!origin.is_none())
               throw ewa::python::UsageError("origin goes with an array volume");
             // A file's spacing replaced, as --spacing does.
             py::dict fileOptions;
             for (const auto& [key, value] : options) fileOptions[key] = value;
             if (!spacing.is_none()) fileOptions["spacing"] = spacing;
             if (source.is_none()) return std::make_unique<PythonScene>("", fileOptions);
             return std::make_unique<PythonScene>(py::str(source).cast<std::string>(), fileOptions);
           }),
           py::arg("source") = py::none(), py::arg("spacing") = py::none(),
           py::arg("origin") = py::none())
      .def(
          "set", [](PythonScene& s, py::kwargs options) { s.set(options); },
          "Keeps render options for later renders (any command-line option but output, "
          "turntable and loading ones), checked now.")
      .def_property_readonly("options", &PythonScene::options, "The render options kept.")
      .def_property(
          "transfer_function", &PythonScene::transferFunction,
          [](PythonScene& s, const py::object& tf) { s.setTransferFunction(tf); },
          "As a dict like the --tf JSON; set a dict or a preset name (ewaview.presets()). With "
          "channel='all', channel 0's.")
      .def_property_readonly("transfer_functions", &PythonScene::transferFunctions,
                             "Every channel's transfer function with channel='all' (a list of "
                             "dicts; one entry otherwise).")
      .def("set_transfer_function", &PythonScene::setTransferFunction, py::arg("tf"),
           py::arg("channel") = 0,
           "Sets channel `channel`'s transfer function (a dict or a preset name) with "
           "channel='all'; IndexError for a channel the scene does not draw.")
      .def(
          "render", [](PythonScene& s, py::kwargs overrides) { return s.render(overrides); },
          "Renders with the kept options and these ones; returns uint8 (H, W, 3).")
      .def(
          "png", [](PythonScene& s, py::kwargs overrides) { return s.png(overrides); },
          "Renders like render() and returns the PNG file's bytes.")
      .def(
          "turntable",
          [](PythonScene& s, const std::filesystem::path& path, int frames, int fps,
             py::kwargs overrides) { s.turntable(path.string(), frames, fps, overrides); },
          py::arg("path"), py::arg("frames") = 36, py::arg("fps") = 30,
          "Writes `frames` pictures over 360 degrees about view-up like --turntable: a .mp4 or "
          ".webm video at `fps`, a %d pattern ending in .png, or a folder of PNGs.")
      .def(
          "tour",
          [](PythonScene& s, const std::filesystem::path& path, int frames, int fps,
             const std::optional<std::filesystem::path>& bookmarks, py::kwargs overrides) {
            s.tour(path.string(), frames, fps, bookmarks ? bookmarks->string() : std::string(),
                   overrides);
          },
          py::arg("path"), py::arg("frames") = 120, py::arg("fps") = 30,
          py::arg("bookmarks") = py::none(),
          "Writes `frames` pictures flying through the camera bookmarks like --tour (the file "
          "`bookmarks`, else NAME.bookmarks.json beside the volume), as turntable() writes them.")
      .def(
          "pick",
          [](PythonScene& s, double x, double y, py::kwargs overrides) {
            return s.pick(x, y, overrides);
          },
          py::arg("x"), py::arg("y"),
          "What pixel (x, y) (column, row from the top left) of render()'s picture shows, as "
          "--pick prints it: a dict with hit, world, index, voxel, value, opacity, distance.")
      .def("_repr_png_", [](PythonScene& s) { return s.png(py::dict()); })
      .def_property_readonly("info", &PythonScene::info,
                             "dims, spacing, type, range (as --info prints) and name.")
      .def_property_readonly("array", &PythonScene::array,
                             "The voxels as loaded: a new array indexed [z, y, x] of the volume's "
                             "type (uint8, int16, uint16 or float32).")
      .def("save_volume", &PythonScene::saveVolume, py::arg("path"), py::arg("crop") = py::none(),
           "Writes the volume (as loaded, after spacing=) to a gzip NRRD (.nrrd), NIfTI-1 "
           "(.nii, .nii.gz), MetaImage (.mha, or .mhd with its .raw) or OME-TIFF (.tif, .tiff) "
           "file, as --save-volume does (what a TIFF cannot keep, its axes, comes "
           "as a UserWarning); with crop=(x0, x1, y0, y1, z0, z1) (world units, as render()'s "
           "crop=) only the voxels whose centres lie in that box.")
      .def("__repr__", &PythonScene::repr);
}
