// The table of ewaview's options: names, groups, values, defaults (read from the settings'
// own defaults) and help, for the parser, --help, the Python module and docs/user/options.md.
#include "app/option_table.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "app/options.h"
#include "core/kernel_lattice.h"
#include "core/synthetic_volume.h"
#include "core/transfer_function_presets.h"
#include "core/value_prefilter.h"
#include "platform/headless_context.h"
#include "render/renderer.h"

namespace ewa {

namespace {

std::string vectorText(const glm::dvec3& v) {
  return numberText(v.x) + "," + numberText(v.y) + "," + numberText(v.z);
}

// The two words of a switch, and the one a setting's default stands for.
std::vector<std::string> onOff() {
  return {"on", "off"};
}
std::string onOff(bool on) {
  return on ? "on" : "off";
}

std::vector<std::string> presetKeys() {
  std::vector<std::string> keys;
  for (const TransferFunctionPresetInfo& p : transferFunctionPresets()) keys.push_back(p.key);
  return keys;
}

std::string joined(const std::vector<std::string>& words, const std::string& comma,
                   const std::string& last) {
  std::string text;
  for (size_t i = 0; i < words.size(); ++i)
    text += (i == 0 ? "" : i + 1 == words.size() ? last : comma) + words[i];
  return text;
}

OptionSpec& add(std::vector<OptionSpec>& rows, const char* name, OptionGroup group) {
  rows.emplace_back();
  rows.back().name = name;
  rows.back().group = group;
  return rows.back();
}

std::vector<OptionSpec> makeTable() {
  const Options o;  // the defaults the parse starts from
  const RenderSettings& r = o.render;
  std::vector<OptionSpec> rows;
  RenderSettings closeUp;
  applyCloseUpSettings(&closeUp);
  const std::string closeUpWords =
      "--classification " + std::string(classificationModeName(closeUp.classification.mode)) +
      " --slab-preintegration " + onOff(closeUp.slabPreintegration) + " --kernel-width " +
      numberText(closeUp.kernelWidth) + " --cutoff " + numberText(closeUp.cutoff);
  add(rows, "file", OptionGroup::Input)
      .value("FILE")
      .notInPython()
      .describe(
          "Volume file (.nrrd .nhdr .mhd .mha .dat .vti .vtk .nii .nii.gz .hdr .img .dcm .tif "
          ".tiff .ome .slc .mrc .map .rec .h5 .hdf5), an OME-Zarr folder (.zarr), a folder of "
          "DICOM, TIFF or .png .jpg .bmp .pgm "
          "slices, an archive of one (.zip .tar .tar.gz .7z ...), or raw with --raw-*")
      .explain(
          "`.nrrd`/`.nhdr`, `.mhd`/`.mha`, `.dat`, `.vti`, legacy VTK `.vtk` (structured "
          "points), `.nii`/`.nii.gz`/`.hdr`/`.img` (NIfTI), any file of a DICOM series (`.dcm`, "
          "with the `DICM` preamble, or an old ACR-NEMA file: a bare data set), `.tif`/`.tiff`, "
          "an OME-TIFF dataset's companion `.ome`/`.ome.xml`, `.slc`, MRC and CCP4 maps "
          "(`.mrc`, `.mrcs`, `.map`, `.ccp4`, `.rec`: cryo-EM and tomography), HDF5 (`.h5`, "
          "`.hdf5`: one 3D dataset, `--dataset`), an OME-Zarr image's folder (`.zarr`, or any "
          "Zarr v2 array's folder, or its `.zattrs` or `.zarray` file: `--level`), a folder (DICOM "
          "series, its own or in the folders below it, as on a CD with a `DICOMDIR`; or TIFF "
          "slices), an archive of any of these as downloads and PACS exports come (`.zip`, "
          "`.tar`, `.tar.gz`/`.tgz`, `.tar.bz2`, `.tar.xz`, `.tar.zst`, `.7z`), or raw data "
          "with `--raw-*` ([Formats](formats.md))");
  add(rows, "--synthetic", OptionGroup::Input)
      .value("SPEC")
      .describe("Synthetic volume: " + joined(syntheticVolumeForms(), ", ", " or "));
  add(rows, "--series", OptionGroup::Input)
      .value("UID")
      .describe(
          "DICOM: open the series with this SeriesInstanceUID (UID#2, ... a part of one that "
          "mixes sizes, orientations or multi-frame files)")
      .explain(
          "DICOM: open the series with this SeriesInstanceUID (default: the named file's "
          "series, else the folder's series with the most slices; `--info` lists them all). A "
          "series that mixes image sizes, orientations (a localizer's three planes) or "
          "multi-frame files is split into the volumes it holds: its largest keeps the UID, the "
          "others are `UID#2`, `UID#3`, ... (largest first)");
  add(rows, "--frame", OptionGroup::Input)
      .value("N")
      .range(0, 1 << 30)
      .defaultsTo(std::to_string(o.load.frame))
      .describe(
          "4D NIfTI or NRRD, an OME-TIFF's, OME-Zarr image's or ImageJ hyperstack's time point, "
          "or a DICOM series of several volumes at the same positions: open this volume")
      .explain(
          "4D NIfTI or NRRD (its last axis a time or list axis, as 3D Slicer's sequences and "
          "DWI files have it), an OME-TIFF's, OME-Zarr image's or ImageJ hyperstack's time "
          "point, or a DICOM "
          "series (or enhanced multi-frame file) of several volumes at the same slice positions "
          "(diffusion directions, echoes, time points): open volume N; `--info` says how many "
          "there are. A DICOM series' volumes are told apart by position: the k-th slice at "
          "each position, by InstanceNumber, is volume k");
  add(rows, "--channel", OptionGroup::Input)
      .value("N")
      .defaultsTo(std::to_string(o.load.channel))
      .describe(
          "Colour or vector data (TIFF, DICOM, image slices and NIfTI: 0 red, 1 green, 2 blue; "
          "MetaImage channels, VTK components and vectors, a 4D NRRD's colour or vector axis, an "
          "OME-Zarr image's channel axis): "
          "open this channel; 'all' or a list (0,2): those channels overlaid, each in its "
          "colour, the colours added (headless: --output, --turntable, --tour)")
      .explain(
          "Multi-channel TIFF (samples per pixel, an ImageJ hyperstack's `channels=`, or an "
          "OME-TIFF's `SizeC`), colour DICOM (RGB, or YBR converted to RGB: 0 red, 1 green, 2 "
          "blue), colour image slices, NIfTI RGB24/RGBA32, MetaImage's "
          "`ElementNumberOfChannels`, a `.vti` array's `NumberOfComponents`, legacy VTK's "
          "SCALARS of several components, COLOR_SCALARS and VECTORS, or a 4D NRRD whose first "
          "axis is colour or vectors (`kinds: RGB-color ...`), or an OME-Zarr image's channel "
          "axis: open channel N. `--channel all`, "
          "headless (with `--output`, `--turntable` or `--tour`): every channel of the file (16 "
          "at most) overlaid (`--channel 0,2`: those channels, in any order, each in the colour "
          "its place in the file gives it; two the same, an empty entry or a channel the file "
          "lacks is a one-line error) as fluorescence viewers (napari, Fiji's composite) show "
          "them: each channel is drawn alone by its own renderer, in its colour, and the "
          "pictures' colours added (where two overlap, white for magenta and green); over a "
          "background that is not black each channel is drawn over white too, for its opacity, "
          "and the background shows through what all of them leave. Each channel's transfer "
          "function is its sidecar (`NAME.tf.json`, `NAME.cC.tf.json`), else the histogram's "
          "default in the channel's colour: magenta and green for two channels (napari's pair), "
          "else Fiji's composite colours in turn: red, green, blue (an RGB file shows its own "
          "colours), grey, cyan, magenta, yellow (the opacities say how much colour each value "
          "gives off; `--tf-preset` applies to each over its range). Its price is the channels' "
          "own frames, twice each over a background that is not black "
          "([docs/performance.md](../dev/performance.md): two channels 1.29× one "
          "over black, 2.17× over grey). Not with `--tf`, `--info`, `--pick` or "
          "`--save-volume`; `--stats` reports the channels' sums and each channel in "
          "`channels`; a file of one channel is drawn as it is; in Python, `Scene(path, "
          "channel=\"all\")` or `channel=(0, 2)`");
  add(rows, "--level", OptionGroup::Input)
      .value("N")
      .range(0, 63)
      .defaultsTo(std::to_string(o.load.level))
      .describe("OME-Zarr: open this pyramid level (0: full resolution, each next one coarser)")
      .explain(
          "OME-Zarr: open level N of the image's multiscales pyramid, the N-th of its "
          "`datasets` (0 is full resolution, each next one coarser); the voxel spacing is the "
          "level's scale. `--info` says how many levels there are. A Zarr array without "
          "multiscales has level 0 alone. A level other than 0 for any other volume is a usage "
          "error naming it");
  add(rows, "--dataset", OptionGroup::Input)
      .value("NAME")
      .describe("HDF5: open this 3D dataset (default: the file's only 3D dataset)")
      .explain(
          "HDF5: open the 3D dataset at this path in the file (`/volume`, `exported_data`, "
          "`group/raw`). Without it the file must hold exactly one 3D dataset; otherwise the "
          "error lists them");
  add(rows, "--spacing", OptionGroup::Input)
      .value("X,Y,Z")
      .describe(
          "Voxel spacing X,Y,Z replacing the file's (image stacks have none; raw files: "
          "--raw-spacing)")
      .explain(
          "Replace the voxel spacing the file gives (or, for image slices, lacks) with `X,Y,Z`, "
          "each positive; a note says what the file had. In the window it holds for the file "
          "named on the command line and its frames and channels, not for other files opened "
          "there");
  add(rows, "--raw-dims", OptionGroup::Input).value("X,Y,Z").describe("Raw input: dims X,Y,Z");
  add(rows, "--raw-type", OptionGroup::Input)
      .value("T")
      .describe(
          "Raw input: int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32 or "
          "float64")
      .explain(
          "Plain raw input; `T` is `int8`, `uint8`, `int16`, `uint16`, `int32`, `uint32`, "
          "`int64`, `uint64`, `float32` or `float64` (32- and 64-bit types are made float32)");
  add(rows, "--raw-spacing", OptionGroup::Input)
      .value("X,Y,Z")
      .defaultsTo(o.rawSpacing)
      .describe("Raw input: spacing X,Y,Z");
  add(rows, "--raw-endian", OptionGroup::Input)
      .value("little|big")
      .defaultsTo(o.rawEndian)
      .describe("Raw input: byte order");
  add(rows, "--allow-outside-data", OptionGroup::Input)
      .describe("Let a detached header (.mhd, .nhdr, .dat) name data files outside its own folder");
  add(rows, "--watch", OptionGroup::Input)
      .notInPython()
      .describe(
          "Window: reload the volume, keeping the view and transfer function, whenever its file "
          "changes (a simulation or scanner writing it; also F5 and the panel)")
      .explain(
          "Window: reload the volume whenever its file changes (a simulation or a scanner "
          "rewriting it; a folder: files added or removed), keeping the camera, page and "
          "transfer function; also the panel's \"reload when the file changes\"");
  add(rows, "--info", OptionGroup::Input)
      .notInPython()
      .describe("Print dims, spacing, type, value range, direction and notes as JSON and exit")
      .explain(
          "Print the volume's dims, spacing, type, value range, origin, direction (rows of the "
          "3×3 matrix D), `space` (`LPS` for patient axes, else `none`), `unit` (of spacing, "
          "origin and world lengths: `mm` for DICOM, from NIfTI's `xyzt_units` (m, mm, µm), a "
          "NRRD's `space units` or `units` when all axes share one, an ImageJ TIFF's `unit=`, "
          "an OME-TIFF's physical size unit, `Å` for MRC maps (`angstrom` and the Ångström sign "
          "read as `Å` too); `null` when the file does not say), `channel` and `channels` "
          "(which channel this is, `--channel`, of how many), `frame` and `frames` (which of "
          "the file's volumes this is, `--frame`, and how many it holds: 1 but for a 4D NIfTI "
          "or NRRD, an OME-TIFF's or ImageJ hyperstack's time points or a DICOM series of "
          "several volumes), `series` (a DICOM folder's series when it holds several: `{\"id\": "
          "\"UID\" or \"UID#2\", \"label\": \"120 slices, AX T1\", \"open\": true}` each, "
          "`--series ID` opens one; else empty) and `notes` (frames in a 4D file, conversions, "
          "the other series in a DICOM folder, warnings) as one JSON object");
  add(rows, "--output", OptionGroup::Output)
      .shortLetter("o")
      .value("FILE")
      .notInPython()
      .describe(
          "Render headless to this PNG and exit (with --turntable or --tour: frames or a video)")
      .explain(
          "Render headless and exit (no display needed); with `--turntable` the frames' pattern "
          "or folder, or a video. A picture is written to a temporary file beside it and "
          "renamed into place (readers never see half a PNG); a FIFO, a character device or a "
          "name of an open file (`/dev/stdout`, `/dev/fd/N`) is written into instead (`-o "
          "/dev/stdout | display -`, `-o /dev/stdout > f.png`, `-o /dev/null` to time with "
          "`--stats`)");
  add(rows, "--resolution", OptionGroup::Output)
      .value("W,H")
      .range(1, 16384)
      .defaultsTo(numberText(o.width) + "," + numberText(o.height))
      .describe("Image or window size W,H");
  add(rows, "--stats", OptionGroup::Output)
      .describe(
          "With --output: print the frame's statistics as one JSON line (times, splats, "
          "gpu_bytes, gpu_bytes_per_splat, peak_rss)")
      .explain(
          "With `--output` (one picture): print the frame's statistics as one JSON line: "
          "`renderer`, `width`, `height`, `render_ms` and the stages `classify_ms`, "
          "`partition_ms`, `splat_ms`, `final_ms`, `splats` (non-transparent voxels), "
          "`splats_drawn`, `slabs`, `slabs_drawn` (before early termination stopped the slab "
          "loop), `slab_entries`, `entries_culled` (of the slab entries, those occlusion "
          "culling did not draw), `slabs_coarse` (slabs splatted into a coarser image: [Slab "
          "image scale](../dev/rendering.md#slab-image-scale)), `slab_passes` (four samples a "
          "slab: "
          "the passes each slab took, 1 or 2; 0 otherwise, and for frames drawn in compute "
          "tiles), `splatter` (`raster`, or `tiles` where `--splatter` drew the frame in "
          "compute tiles, `cpu` where the CPU splatter drew it, with its stages "
          "`cpu_records_ms`, `cpu_bin_ms`, `cpu_tiles_ms` and `cpu_bytes_per_splat`: its splat "
          "records and tile bins at their largest, per splat), `note` (only when the frame was not "
          "drawn as asked: why, in one "
          "line), `gpu_partition` (whether the GPU's slab partition drew the frame, `auto` on a "
          "hardware GPU: its order of a slab's entries varies between runs, and two runs' "
          "pictures with it, by up to 3 levels on an H200; the CPU's partition draws the same "
          "picture to the bit), `gpu_bytes` (GL buffers and textures the renderer holds; 0 "
          "where it does not count them), `gpu_bytes_per_splat` (null then), `peak_rss` (bytes) "
          "and `huge_pages` (whether large allocations get transparent huge pages: [One-shot "
          "pictures and files](../dev/performance.md#one-shot-pictures-and-files)). With "
          "`--channel all` (or a list of channels) the times, counts and bytes are the "
          "channels' sums (`slab_passes` the most any took, the notes joined) and `channels` "
          "lists each channel's own, in the order drawn. See "
          "[Performance](../dev/performance.md#reading---stats)");
  add(rows, "--turntable", OptionGroup::Output)
      .value("N")
      .range(1, 100000)
      .notInPython()
      .describe(
          "Render N frames over 360 degrees about view-up; --output is a pattern with one %d "
          "(frame_%03d.png), a folder, or a video (.mp4: H.264, .webm: VP9)")
      .explain(
          "Render N frames over 360° about the camera's view-up through the focal point (frame "
          "0 is the starting camera) with the `--renderer` chosen, and exit; `--output` is a "
          "video (`.mp4`: H.264 through libx264, `.webm`: VP9 through libvpx-vp9), a pattern "
          "with one `%d`/`%0Nd` ending in `.png`, or else a folder (made if missing) that gets "
          "`frame_000.png`, `frame_001.png`, ... PNG frames are encoded on worker threads while "
          "the next frames render (a 36-frame 1024² turntable on an H200: 0.9–1.4 s, against "
          "7–9 s when each frame was encoded in turn: [Turntables and PNG "
          "frames](../dev/performance.md#one-shot-pictures-and-files)). Progress shows on a "
          "terminal");
  add(rows, "--tour", OptionGroup::Output)
      .value("N")
      .range(2, 100000)
      .notInPython()
      .describe(
          "Render N frames flying through the camera bookmarks in order (the window's, with "
          "their crop boxes and planes), resting at each; --output as --turntable")
      .explain(
          "Render N frames (2 or more) flying through the camera bookmarks in their order, each "
          "leg eased in and out so the view rests at every bookmark (the focal point on a "
          "straight line, the orientation by the shortest turn, the distance at an even zoom, "
          "each bookmark's crop box moving to the next one's; planes and the projection switch "
          "half way), and exit; the first and last frames are the first and last bookmarks; "
          "`--output` as for `--turntable`; not with `--crop` or `--clip-plane` (the bookmarks "
          "carry them)");
  add(rows, "--bookmarks", OptionGroup::Output)
      .value("FILE")
      .notInPython()
      .describe("The camera bookmarks --tour flies through")
      .explain(
          "The bookmarks `--tour` flies through (default: where the window's \"Camera "
          "bookmarks\" keep the volume's: `NAME.bookmarks.json` beside it, else, for a volume "
          "in a read-only folder or a synthetic one, under the settings folder, "
          "`CONFIG/bookmarks/`, `CONFIG` as the window finds it or `--config-dir`; only read)");
  add(rows, "--fps", OptionGroup::Output)
      .value("F")
      .range(1, 240)
      .defaultsTo(std::to_string(o.fps))
      .notInPython()
      .describe("Frames per second of a --turntable or --tour video");
  add(rows, "--pick", OptionGroup::Output)
      .value("X,Y")
      .notInPython()
      .describe(
          "Print what pixel X,Y (column, row from the top left) of the --resolution picture "
          "shows (world point, voxel, value) as JSON and exit")
      .explain(
          "Print, as one JSON line, what pixel X,Y (column and row from the top left) of the "
          "picture the same options would render shows, and exit (no OpenGL needed): the point "
          "along the pixel's ray where the opacity accumulated front to back through the "
          "trilinear field reaches half the ray's total (the surface of an opaque object, the "
          "middle of a haze; `--render-mode mip`: the brightest point the transfer function "
          "shows), within the data's box and the crop box and clipping planes; `world` (world "
          "coordinates), `index` (continuous voxel coordinates), `voxel` (the nearest voxel), "
          "`value` (the data's trilinear value there), `opacity` (the ray's total), `distance` "
          "(from the eye, or from the view plane in parallel projection); `\"hit\":false` where "
          "the pixel shows nothing (total opacity under 0.01). The window shows the same under "
          "the cursor ([The window](window.md))");
  add(rows, "--save-volume", OptionGroup::Output)
      .value("FILE")
      .notInPython()
      .describe(
          "Write the volume as opened (any format, after --frame, --channel, --series, "
          "--spacing; with --crop only the box's voxels) to this file and exit: .nrrd (gzip), "
          ".nii or .nii.gz (NIfTI-1), .mha or .mhd with .raw (MetaImage), .tif or .tiff "
          "(OME-TIFF)")
      .explain(
          "Write the volume as opened (any format, after `--series`, `--frame`, `--channel`, "
          "`--spacing`) and exit (with `--info`, print it too), in the format the name ends in. "
          "`FILE.nrrd`: an attached gzip NRRD file: voxels in the volume's type, sizes, spacing "
          "and direction as `space directions`, origin, the patient frame (`space: "
          "left-posterior-superior`), the unit as `space units`, the notes as comments; what "
          "ewaview reads back is the same volume. `FILE.nii`, `FILE.nii.gz` (gzip): a "
          "single-file NIfTI-1 image (NIfTI-2 where NIfTI-1 cannot hold the volume, below): "
          "voxels in the volume's type (no scaling), the voxel-to-world matrix as both the "
          "sform and the qform (code 1, scanner; NIfTI's RAS is the viewer's LPS with x and y "
          "negated; no qform when the axes are not orthogonal), the unit in `xyzt_units` when "
          "NIfTI names it (m, mm, µm; another unit is left out), no notes; it reads back with "
          "the same voxels and places to float precision (NIfTI-1 stores float32), and with "
          "patient axes: a volume that has none is written with pixdim alone when it lies at "
          "the origin on the world's axes (and reads back as it was), else with its matrix, and "
          "so opens again with patient axes (NIfTI has no other world); a volume with an axis "
          "over 32767 voxels, or a spacing or origin beyond float32's range (NIfTI-1's limits), "
          "is written as NIfTI-2 instead (its 540-byte header of 64-bit sizes and doubles: the "
          "placement to the last digit), with a note saying so, since tools that read NIfTI-1 "
          "only will not open it. `FILE.mha`: a MetaImage file with its data inside, as ITK "
          "writes one: voxels in the volume's type, zlib-compressed, `ElementSpacing`, `Offset` "
          "and `TransformMatrix` (each axis's direction in turn, LPS) to the last digit, and "
          "for patient axes `AnatomicalOrientation` (the side each axis starts from: `RAI` for "
          "the identity); MetaImage has no unit or notes, so they are left out; it reads back "
          "as the same volume but for the unit. `FILE.mhd`: the same header, uncompressed, "
          "naming `FILE.raw` beside it, which holds the voxels little-endian (written first, so "
          "the header never names a file not yet there; the window's Save asks before replacing "
          "either). `FILE.tif`, `FILE.tiff` (`.ome.tif` too): an OME-TIFF stack, one page a "
          "slice, rows from the first (y = 0), in the volume's type (float32 as 32-bit float), "
          "deflate-compressed, the first page's description the OME-XML naming the pixel size "
          "and slice spacing to the last digit with their unit (`mm`, `µm`, `nm`, `cm`, `m`, "
          "`pm`, `Å`; OME's `reference frame` when the volume has none), and the resolution "
          "tags per centimetre for readers that know no OME; an origin not at zero is each "
          "slice's OME `Plane` position (`PositionX`, `PositionY`, `PositionZ`, in the same "
          "unit), as Bio-Formats writes stage positions, and ewaview reads the first plane's "
          "position back as the origin; it is the OME-TIFF that Bio-Formats (Fiji, QuPath) and "
          "tifffile (napari) read; checked with tifffile 2023.2 (Debian's `python3-tifffile`, "
          "not a dependency): the same voxels, sizes and units, and with ewaview itself. TIFF "
          "keeps no axis directions or patient frame: the file is written as the slices are "
          "stored and reads back on the world's axes, and a one-line note on stderr (`ewaview: "
          "note: FILE: TIFF keeps no patient axes ...`; the window's message, a Python warning) "
          "says what was left out. With `--crop X0,X1,Y0,Y1,Z0,Z1`, only the voxels whose "
          "centres lie in that world box, where they were (for a grid turned against the "
          "world's axes, the index range holding them all; a box beside the volume is an error; "
          "not with `--clip-plane`: a plane cannot cut a grid). Not with `--output`, "
          "`--turntable` or `--pick`");
  add(rows, "--camera-position", OptionGroup::Camera)
      .value("X,Y,Z")
      .describe("Camera position X,Y,Z")
      .explain("Eye position (default: framing the whole volume from +z)");
  add(rows, "--camera-focal-point", OptionGroup::Camera)
      .value("X,Y,Z")
      .describe("Camera focal point X,Y,Z")
      .explain("Point looked at (default: the volume's centre)");
  add(rows, "--camera-view-up", OptionGroup::Camera)
      .value("X,Y,Z")
      .describe("Camera view-up X,Y,Z");
  add(rows, "--camera-view-angle", OptionGroup::Camera)
      .value("DEG")
      .range(0.01, 179.0)
      .defaultsTo(numberText(o.cameraViewAngle))
      .describe("Vertical view angle in degrees");
  add(rows, "--camera-orthographic", OptionGroup::Camera)
      .describe("Orthographic projection")
      .explain(
          "Parallel projection showing the height `2·distance·tan(angle/2)` at the focal point");
  add(rows, "--axis", OptionGroup::Camera)
      .describe(
          "Draw the orientation axes in the picture's bottom-right corner (X, Y, Z; L, P, S for "
          "patient axes); the window shows them unless switched off (X key)")
      .explain(
          "Draw the orientation axes in the picture's bottom-right corner: the world's x, y and "
          "z axes (red, green, blue) as the camera turns them, labelled X, Y, Z, or L, P, S for "
          "a volume with patient axes (LPS: the patient's left, back and head); in headless "
          "pictures, turntable frames and Python's `render(axis=True)`. The window shows them "
          "anyway unless switched off (`X`)");
  add(rows, "--record-camera-path", OptionGroup::Camera)
      .value("FILE")
      .notInPython()
      .describe(
          "Window: write the cameras the window drew to this file on exit, for "
          "ewaview-interact-bench --path")
      .explain(
          "Window: on exit, write the camera of each moving frame the window drew to FILE, in "
          "the format `ewaview-interact-bench --path` replays ([interaction "
          "speed](../dev/performance.md#interaction))");
  add(rows, "--tf", OptionGroup::TransferFunction)
      .value("FILE")
      .describe("Transfer function JSON file");
  add(rows, "--tf-preset", OptionGroup::TransferFunction)
      .accepts(presetKeys())
      .describe(
          "Apply a preset to the transfer function (--tf's, the sidecar's or the histogram's): "
          "ct-bone, ct-soft-tissue, mr, grayscale-ramp replace it; the colour maps viridis, "
          "inferno, cool-to-warm, rainbow recolour it (repeat: in order)")
      .explain(
          "Apply a preset to the transfer function the volume opens with (`--tf`'s, the "
          "sidecar's or the histogram's), as the editor's preset menu does: `ct-bone`, "
          "`ct-soft-tissue` (Hounsfield units, stretched over a range that is not), `mr`, "
          "`grayscale-ramp` replace it; the colour maps `viridis`, `inferno`, `cool-to-warm`, "
          "`rainbow` recolour it and keep its opacity; repeat to apply several in order "
          "(`--tf-preset mr --tf-preset inferno`); in the window, to the first volume (as "
          "`--tf`)");
  add(rows, "--classification", OptionGroup::TransferFunction)
      .accepts(classificationModeNames())
      .defaultsTo(classificationModeName(r.classification.mode))
      .describe(
          "Transfer function applied per pixel to the splatted value (post) or per voxel before "
          "splatting (pre; the default with surface splats)")
      .explain(
          "Transfer function applied per pixel to each slab's splatted value (`post`, default; "
          "composite mode; no surface splats) or to each voxel before splatting (`pre`, the "
          "papers' way; the default when surface splats are asked for). X-ray and MIP are "
          "always pre-classified");
  add(rows, "--renderer", OptionGroup::Rendering)
      .accepts(rendererKindNames())
      .defaultsTo(rendererKindName(r.renderer))
      .describe("splat (GPU EWA splatting) or shearwarp (CPU)")
      .explain(
          "EWA splatting on the GPU (default) or the CPU shear-warp renderer ([shear-warp "
          "renderer](../dev/rendering.md#shear-warp-renderer))");
  add(rows, "--render-mode", OptionGroup::Rendering)
      .accepts(renderModeNames())
      .defaultsTo(renderModeName(r.mode))
      .describe(
          "Slab compositing, the summed optical depth as gray (xray) or the largest value (mip)")
      .explain(
          "Slab compositing (default), the summed optical depth as gray, or the maximum value "
          "([render modes](../dev/rendering.md#shading-surface-splats-and-render-modes))");
  add(rows, "--filter", OptionGroup::Rendering)
      .accepts(filterModeNames())
      .defaultsTo(filterModeName(r.filter))
      .describe("Splat filter: EWA, Swan's or none (plain)");
  add(rows, "--kernel-width", OptionGroup::Rendering)
      .value("S")
      .range(kMinKernelWidth, kMaxKernelWidth)
      .defaultsTo(numberText(r.kernelWidth))
      .describe("Kernel sigma in voxel spacings")
      .explain(
          "Kernel standard deviation in voxel spacings per axis (the default, with "
          "cutoff 5 the narrowest kernel that does not show the lattice; the paper's is 1); the "
          "mass per voxel is unchanged ([Kernel "
          "width](../dev/rendering.md#kernel-width))");
  add(rows, "--cutoff", OptionGroup::Rendering)
      .value("C")
      .range(0.25, 64.0)
      .defaultsTo(numberText(r.cutoff))
      .describe("Footprint cutoff r = dx^T Q dx")
      .explain("Footprint cutoff on `r = Δxᵀ Q Δx` (the paper's is 4)");
  add(rows, "--depth-cutoff", OptionGroup::Rendering)
      .value("D")
      .range(0.25, double(INFINITY))
      .defaultsTo(numberText(r.depthCutoff))
      .describe("Kernels' depth extent in squared sigmas")
      .explain(
          "Kernels' depth extent in squared standard deviations, 0.25 and up, or `inf`: each "
          "kernel's depth profile is cut at `√D·σ` (at most the cutoff) and it is drawn only in "
          "the slabs that reach; `inf` is the uncut Gaussian ([Depth "
          "profile](../dev/rendering.md#depth-profile))");
  add(rows, "--low-pass", OptionGroup::Rendering)
      .value("V")
      .accepts({"auto"})
      .range(0.1, 1.0)
      .defaultsTo(r.lowPass == 0.0 ? "auto" : numberText(r.lowPass))
      .describe(
          "EWA's screen low-pass filter: its variance in pixels^2, or auto (1, the paper's, "
          "in every mode)")
      .explain("[Low-pass filter](../dev/rendering.md#low-pass-filter)");
  add(rows, "--close-up", OptionGroup::Rendering)
      .describe("Close-up setting, today the defaults: " + closeUpWords +
                "; options given beside it win")
      .explain("The close-up setting, today the defaults: `" + closeUpWords +
               "` (the panel's \"close-up\" button restores them and the default `--prefilter`; "
               "options given beside it win) "
               "([Kernel width](../dev/rendering.md#kernel-width))");
  add(rows, "--slab-preintegration", OptionGroup::Rendering)
      .accepts(onOff())
      .defaultsTo(onOff(r.slabPreintegration))
      .describe(
          "Post-classification: classify each pixel's values in two neighbouring slabs as a "
          "pair through the pre-integration table (on), or each slab's value alone (off)")
      .explain(
          "With `--classification post`: classify each pixel's values in two neighbouring slabs "
          "as a pair through the pre-integration table (`on`, default; thin transfer-function "
          "peaks are not missed between slabs) or each slab's value alone (`off`) "
          "([Pre-integration between "
          "slabs](../dev/rendering.md#pre-integration-between-slabs))");
  add(rows, "--slab-samples", OptionGroup::Rendering)
      .accepts({"4", "2"})
      .defaultsTo(std::to_string(r.slabSamples))
      .describe(
          "Post-classified and pre-integrated: each slab's values at 4 depths (its quarters) or "
          "2 (its halves; cheaper, softer in depth)")
      .explain(
          "With `--classification post` and pre-integration: each slab's values at 4 depths, "
          "its quarters (default: nearer a ray caster close up) or 2, its halves (cheaper, "
          "softer in depth) ([Four samples a "
          "slab](../dev/rendering.md#four-samples-a-slab))");
  add(rows, "--prefilter", OptionGroup::Rendering)
      .value("B")
      .range(0.0, kMaxPrefilter)
      .defaultsTo(numberText(r.classification.prefilter))
      .describe(
          "Post-classification: sharpen each splat's value by B times its discrete Laplacian, "
          "so the kernels come nearer interpolating the voxels (0: the data's values)")
      .explain(
          "With `--classification post` (composite mode): each splat carries its value "
          "sharpened by `B` times its discrete Laplacian, `v + B·(6v − Σ 6 neighbours)`, so the "
          "kernels come nearer interpolating the voxels as a ray caster's trilinear samples do; "
          "0: the data's values. Which voxels are drawn, their "
          "normals, pre-classification, X-ray and MIP are untouched ([Value "
          "prefilter](../dev/rendering.md#value-prefilter))");
  add(rows, "--slab-thickness", OptionGroup::Rendering)
      .value("T")
      .range(0.25, 1000.0)
      .defaultsTo(numberText(r.slabThickness))
      .describe("Slab thickness in voxel depths along the view");
  add(rows, "--compositing", OptionGroup::Rendering)
      .accepts(compositeOrderNames())
      .defaultsTo(compositeOrderName(r.order))
      .describe("Slab order")
      .explain("Slab order (default front to back, with early termination)");
  add(rows, "--termination", OptionGroup::Rendering)
      .value("A")
      .range(0.5, 1.0)
      .defaultsTo(numberText(r.terminationOpacity))
      .describe("Front to back: stop a pixel at this opacity (1 never stops)")
      .explain(
          "Front to back: a pixel takes no more slabs once its opacity reaches `A` (1 never "
          "stops)");
  add(rows, "--xray-map", OptionGroup::Rendering)
      .accepts(xrayMapNames())
      .defaultsTo(xrayMapName(r.xrayMap))
      .describe("X-ray gray: exp(-K sum) (exp) or K sum (sum)");
  add(rows, "--xray-scale", OptionGroup::Rendering)
      .value("K")
      .range(1e-6, 1e6)
      .defaultsTo(numberText(r.xrayScale))
      .describe("X-ray: optical depth multiplied by K");
  add(rows, "--background", OptionGroup::Rendering)
      .value("R,G,B")
      .range(0.0, 1.0)
      .defaultsTo(vectorText(r.background))
      .describe("Background colour R,G,B");
  add(rows, "--crop", OptionGroup::Rendering)
      .value("X0,X1,Y0,Y1,Z0,Z1")
      .describe("Keep only the world-space box X0,X1,Y0,Y1,Z0,Z1 (every renderer and mode)")
      .explain(
          "Draw only the world-space box `[X0,X1]×[Y0,Y1]×[Z0,Z1]` (every renderer and render "
          "mode; [below](crop-and-clip.md))");
  add(rows, "--clip-plane", OptionGroup::Rendering)
      .value("PX,PY,PZ,NX,NY,NZ")
      .describe(
          "Keep the half-space in front of the plane through PX,PY,PZ with normal NX,NY,NZ "
          "(repeat for up to 6 planes; --clip-plane=-1,... for a leading minus)");
  add(rows, "--shading", OptionGroup::Shading)
      .describe("Phong shading with a head light")
      .explain("Phong shading with a head light, per splat (off by default)");
  add(rows, "--ambient", OptionGroup::Shading)
      .value("A")
      .range(0.0, 4.0)
      .defaultsTo(numberText(r.lighting.ambient))
      .describe("Ambient light term");
  add(rows, "--diffuse", OptionGroup::Shading)
      .value("D")
      .range(0.0, 4.0)
      .defaultsTo(numberText(r.lighting.diffuse))
      .describe("Diffuse light term");
  add(rows, "--specular", OptionGroup::Shading)
      .value("S")
      .range(0.0, 4.0)
      .defaultsTo(numberText(r.lighting.specular))
      .describe("Specular light term");
  add(rows, "--shininess", OptionGroup::Shading)
      .value("N")
      .range(1.0, 1000.0)
      .defaultsTo(numberText(r.lighting.shininess))
      .describe("Specular exponent");
  add(rows, "--gradient", OptionGroup::Shading)
      .accepts(gradientModeNames())
      .defaultsTo(gradientModeName(r.classification.gradient))
      .describe("Gradients by central differences or smoothed (Sobel-like)")
      .explain(
          "Gradients (the splats' voxel normals, surface splats and the ray normals' texture) "
          "by central differences (default) or smoothed across each axis by `[1 2 1]` "
          "(Sobel-like)");
  add(rows, "--post-normals", OptionGroup::Shading)
      .accepts(postNormalsNames())
      .defaultsTo(postNormalsName(r.postNormals))
      .describe(
          "Post-classified, with --shading: normals from the gradient of the reconstructed "
          "field (field; pre-integrated only, else voxel), the splats' voxel normals (voxel), "
          "or the data's gradient read along each pixel's ray (ray: as a ray caster shades; 4 "
          "bytes of GPU memory a voxel while shading)")
      .explain(
          "With `--classification post` and `--shading`: each ray segment lit by the data's "
          "gradient read along the pixel's ray (`ray`, default: as a ray caster shades; a 3D "
          "texture of 4 bytes a voxel while shading), or each pixel by the gradient of the "
          "reconstructed field (`field`, pre-integrated only; shows the slab period as stripes "
          "on oblique surfaces) or by the splats' voxel normals (`voxel`); also the panel's "
          "\"normals\" "
          "([Post-classification](../dev/rendering.md#post-classification))");
  add(rows, "--surface-threshold", OptionGroup::Shading)
      .value("V")
      .describe("Surface splats on the iso-surface of this data value");
  add(rows, "--surface-opacity-threshold", OptionGroup::Shading)
      .value("A")
      .range(0.0, 1.0)
      .describe("Surface splats where the transfer function's opacity crosses this")
      .explain(
          "Or: where the transfer function's opacity crosses `A`, among voxels whose gradient "
          "is at least `G` of the value range per voxel");
  add(rows, "--surface-min-gradient", OptionGroup::Shading)
      .value("G")
      .range(0.0, 1.0)
      .defaultsTo(numberText(r.classification.minGradient))
      .describe(
          "With --surface-opacity-threshold: least gradient, as a fraction of the value range "
          "per voxel");
  add(rows, "--surface-opacity", OptionGroup::Shading)
      .value("A")
      .range(0.0, 0.999999)
      .defaultsTo(numberText(r.surfaceOpacity))
      .describe("Opacity of the surface-splat layer seen along its normal");
  add(rows, "--preintegrated", OptionGroup::ShearWarp)
      .describe("Shear-warp: pre-integrated slabs between slices")
      .explain("Shear-warp: pre-integrated slabs between slices instead of point samples");
  add(rows, "--table-lookup", OptionGroup::ShearWarp)
      .accepts(tableLookupNames())
      .defaultsTo(tableLookupName(r.shearWarp.lookup))
      .describe("Shear-warp pre-integration table lookup");
  add(rows, "--opacity-correction", OptionGroup::ShearWarp)
      .accepts(onOff())
      .defaultsTo(onOff(r.shearWarp.opacityCorrection))
      .describe("Shear-warp opacity and colour correction for the view's sample distance");
  add(rows, "--buffer-slices", OptionGroup::ShearWarp)
      .accepts(bufferSlicesNames())
      .defaultsTo(bufferSlicesName(r.shearWarp.buffers))
      .describe(
          "Shear-warp buffer slices: two slice-sized (slice) or one intermediate-image-sized "
          "(image)");
  add(rows, "--intermediate-scale", OptionGroup::ShearWarp)
      .value("N")
      .range(1.0, 4.0)
      .defaultsTo(numberText(r.shearWarp.intermediateScale))
      .describe(
          "Shear-warp: at most this many intermediate-image pixels a voxel where the picture is "
          "finer (1: Lacroute's one a voxel)")
      .explain(
          "Shear-warp: at most N intermediate-image pixels a voxel where the picture is finer; 1 "
          "is Lacroute's one a voxel, whose close-ups the warp "
          "magnifies into blocks");
  add(rows, "--splatter", OptionGroup::Advanced)
      .accepts(splatterNames())
      .defaultsTo(splatterName(r.splatter))
      .describe(
          "Frames: rasterized slab by slab (raster), in compute tiles (tiles: no rasterizer, "
          "no blending; front to back, post-classified only with 4 samples a slab and, "
          "shaded, field or ray normals, else rasterized), on the CPU (cpu: every mode, "
          "order and shading), or auto (the CPU on software GL, "
          "else the faster as timed frames find it)")
      .explain(
          "How frames (headless pictures, turntables, Python's `render`, the window) are "
          "splatted: on the CPU in screen tiles over every core (`cpu`: composite pre- and "
          "post-classified with 4, 2 or 1 samples a slab, front to back or back to front, "
          "X-ray and MIP, cropped and clipped, shaded with ray, field or voxel normals, the "
          "same C++ formulas the shaders mirror; in the window the "
          "frame is drawn on a worker thread at a lower priority and shown when done), "
          "rasterized slab by slab (`raster`), in compute tiles (`tiles`: each "
          "screen tile's slabs added up, classified and composited in one work group, no "
          "rasterizer and no blending; [Compute EWA "
          "splatting](../dev/performance.md#compute-ewa-splatting)), or `auto` (default): "
          "on the CPU on a software rasterizer (llvmpipe, softpipe: [Software "
          "OpenGL](../dev/performance.md#software-opengl-the-cpu-splatter)); on a GPU the "
          "first timed frame in tiles (a "
          "frame that compiled the tiles' programs or made their buffers is not counted: the "
          "next tries them again), the next rasterized, then the faster a slab entry, the other "
          "retried every 32 frames or, when it is more than twice as dear, every 32 × (ratio − "
          "1) up to 256 (so a single picture is drawn in tiles), and volumes of more than 8 M "
          "splats always rasterized (the tiles' memory). A volume whose tiles' splat records "
          "(64 bytes a splat) exceed the GL's largest storage block "
          "(`GL_MAX_SHADER_STORAGE_BLOCK_SIZE`: 2047 MiB on the H200, about 33 M splats) is "
          "rasterized even under `tiles`, with a `note`. Where the tiles' programs do not build "
          "on a GPU's compiler, `auto` rasterizes and says so (once on stderr; in `--stats`' "
          "`note` and the window's statistics panel, which also shows `splatter "
          "raster|tiles|cpu`). "
          "The tiles draw front-to-back frames, cropped and clipped too, pre-classified or "
          "post-classified with four samples a slab (and, shaded, ray or field normals); other "
          "frames (back to front, two samples a slab, voxel normals, X-ray, MIP) are "
          "rasterized. The window's full-quality refinement (budgeted steps) follows `auto` "
          "too: on a GPU its frame is drawn whole in tiles in one step where they are the "
          "faster and their last frame there would take at most 80 ms (the first try always); "
          "otherwise, and under an explicit `tiles`, in rasterized chunks. The picture is the "
          "rasterized one within a few levels; `--stats` says which drew it (`splatter`). On "
          "llvmpipe tiles are 5–14× slower (the default post-classified frame 11–14×); on an "
          "H200 the default post-classified frame in tiles took 0.06–0.09× the rasterized one "
          "at 1024² (8.0, 4.7 and 11.7 ms for engine, bonsai and CThead: [On a "
          "GPU](../dev/performance.md#on-a-gpu)). Command line and Python only: the window takes "
          "it "
          "from its command line for its coarse levels and its refinement; not in the panel or "
          "the saved settings");
  add(rows, "--slab-passes", OptionGroup::Advanced)
      .accepts(slabPassesNames())
      .defaultsTo(slabPassesName(r.slabPasses))
      .describe(
          "With 4 samples a slab: splat each slab's kernels once into both of its images (1) or "
          "once into each (2: the same picture, faster on some GPUs); auto: 1 on software "
          "rasterizers, elsewhere whichever timed frames find faster")
      .explain(
          "With four samples a slab: splat each slab's kernels once into both of its images (1) "
          "or once into each (2): the same picture to the bit, twice the vertex work and, for "
          "kernels that reach both halves of the slab, twice the fragments, for half the "
          "blending a pass; each pass leaves out the kernels whose cut depth profile misses its "
          "half of the slab ([Two passes, each its "
          "half](../dev/performance.md#two-passes-each-its-half)). On an H200 at 1024², before "
          "that "
          "culling, 0.57–0.64× the frame for CThead and engine, 1.16× for bonsai; 1.4–1.7× the "
          "splat stage on llvmpipe. `auto` (default): one pass on software rasterizers; on a "
          "GPU, whose timers time each frame, the first frames try one pass and two (a way's "
          "first frame in a renderer not counted: it pays for what the driver makes on first "
          "use), later frames take the faster (the other retried every 32 frames, less often "
          "when it is more than twice as dear: `TwoWayTuner`), so a single headless picture "
          "takes one pass ([On a GPU](../dev/performance.md#on-a-gpu)). `--stats` reports "
          "`slab_passes`. Command line only (not in the panel or the saved settings)");
  add(rows, "--occlusion-culling", OptionGroup::Advanced)
      .accepts(occlusionCullingNames())
      .defaultsTo(occlusionCullingName(r.occlusionCulling))
      .describe(
          "Front to back with termination: skip splats over pixels already opaque (on), draw "
          "them (off), or auto (on, but off on software rasterizers); the picture is the same")
      .explain(
          "Front to back with termination: splats whose whole rectangle lies over pixels "
          "already that opaque are not drawn; the picture is the same ([how it "
          "renders](../dev/rendering.md#occlusion-culling)). `auto` (default): on, but off on "
          "software "
          "rasterizers (llvmpipe), where it measured slower unless most splats are hidden. "
          "Pre-classified frames only: post-classified ones are never culled (culling changed "
          "their picture)");
  add(rows, "--slab-resolution", OptionGroup::Advanced)
      .accepts({"auto", "full"})
      .defaultsTo(r.coarseSlabs ? "auto" : "full")
      .describe(
          "Composite: splat each slab into an image as coarse as its kernels allow (auto: 1.25 "
          "to 4 pixels a texel in quarter steps, where every footprint stays 2 texels wide, "
          "read back bilinearly; not with shaded post-classification) or at the picture's "
          "resolution (full)");
  add(rows, "--slab-precision", OptionGroup::Advanced)
      .accepts(slabPrecisionNames())
      .defaultsTo(slabPrecisionName(r.slabPrecision))
      .describe(
          "Composite: slab images of half floats (half: within a few levels of float, about "
          "twice as fast on a GPU) or floats (float); auto: half for kernel widths up to 1 "
          "unless shaded and post-classified");
  add(rows, "--backend", OptionGroup::Advanced)
      .accepts(platform::headlessBackendNames())
      .defaultsTo(platform::headlessBackendNames().front())
      .describe("Headless OpenGL (EWAVIEW_BACKEND names the default)")
      .explain(
          "Headless OpenGL (the default, or what the environment variable `EWAVIEW_BACKEND` "
          "names; `egl` runs where OSMesa is gone and on GPU machines without "
          "X: [On a GPU](../dev/performance.md#on-a-gpu))");
  add(rows, "--shader-dir", OptionGroup::Advanced)
      .value("DIR")
      .describe("Load shaders from this folder (development)")
      .explain(
          "Read shaders from `DIR` instead of the copies built into the binary (for shader "
          "development)");
  add(rows, "--config-dir", OptionGroup::Advanced)
      .value("DIR")
      .notInPython()
      .describe(
          "Window settings folder (default $EWAVIEW_CONFIG_DIR, else $XDG_CONFIG_HOME/ewaview "
          "or ~/.config/ewaview)");
  add(rows, "--split", OptionGroup::Advanced)
      .accepts({"visible", "voxels"})
      .defaultsTo(o.split)
      .notInPython()
      .describe("ewaview-mpi: balance the ranks' bricks by visible voxels or by voxel count")
      .explain(
          "`ewaview-mpi` only: how the volume is cut into one brick per rank. `visible` (the "
          "default) balances the bricks by the voxels the transfer function shows (counted per "
          "block of 8³ voxels; post-classified with the margin of voxels beside them), so ranks "
          "whose part is empty space do not idle while others draw, a hidden voxel weighing an "
          "eighth of a shown one so that a brick of empty space stays within a rank's memory; "
          "`voxels` by voxel count "
          "([Distributed rendering](../dev/distributed.md))");
  add(rows, "--help", OptionGroup::Advanced)
      .shortLetter("h")
      .notInPython()
      .describe("Print this help and exit");
  add(rows, "--version", OptionGroup::Advanced)
      .notInPython()
      .describe("Print the version and exit");
  return rows;
}

}  // namespace

const char* optionGroupTitle(OptionGroup group) {
  switch (group) {
    case OptionGroup::Input:
      return "Input";
    case OptionGroup::Output:
      return "Output";
    case OptionGroup::Camera:
      return "Camera";
    case OptionGroup::TransferFunction:
      return "Transfer function";
    case OptionGroup::Rendering:
      return "Rendering";
    case OptionGroup::Shading:
      return "Shading";
    case OptionGroup::ShearWarp:
      return "Shear-warp";
    case OptionGroup::Advanced:
      return "Advanced";
  }
  return "?";
}

std::string OptionSpec::cliName() const {
  return shortName.empty() ? name : "-" + shortName + "," + name;
}

std::string OptionSpec::keyword() const {
  std::string key = name.substr(name.find_first_not_of('-'));
  for (char& c : key)
    if (c == '-') c = '_';
  return key;
}

std::string OptionSpec::rangeText() const {
  if (!min || !max) return "";
  auto text = [](double v) {  // every digit: 1073741824, not 1.07374e+09
    std::ostringstream out;
    out << std::setprecision(15) << v;
    return out.str();
  };
  if (std::isinf(*max)) return text(*min) + " and up, or inf";
  return text(*min) + " to " + text(*max);
}

std::string OptionSpec::description() const {
  std::string text = help;
  if (const std::string r = rangeText(); !r.empty()) text += ", " + r;
  if (!defaultText.empty()) text += " (default " + defaultText + ")";
  return text;
}

const std::vector<OptionSpec>& optionTable() {
  static const std::vector<OptionSpec> table = makeTable();
  return table;
}

const OptionSpec& optionSpec(const std::string& name) {
  for (const OptionSpec& spec : optionTable())
    if (spec.name == name) return spec;
  throw std::logic_error("option " + name + " has no row in option_table.cpp");
}

const OptionSpec* optionForKeyword(const std::string& keyword) {
  for (const OptionSpec& spec : optionTable())
    if (spec.keyword() == keyword) return &spec;
  return nullptr;
}

}  // namespace ewa
