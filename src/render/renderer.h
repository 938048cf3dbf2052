// Renderer: the interface every volume renderer implements, and the settings they share.
#pragma once

#include <cmath>
#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/clip_region.h"
#include "core/ewa_footprint.h"
#include "core/image8.h"
#include "core/shading.h"
#include "core/shear_warp_settings.h"
#include "core/splat_attributes.h"
#include "core/transfer_function.h"
#include "core/volume.h"
#include "core/volume_pick.h"

namespace ewa {

// composite: slabs composited with opacity 1 - exp(-depth); xray: the summed optical depth
// shown as gray; mip: the largest classified value along each pixel's footprint.
enum class RenderMode { Composite = 0, XRay = 1, Mip = 2 };
enum class CompositeOrder { FrontToBack = 0, BackToFront = 1 };
// X-ray gray: exp(-scale * sum) (light through the volume) or scale * sum.
enum class XRayMap { Attenuation = 0, Sum = 1 };

const char* renderModeName(RenderMode mode);
bool parseRenderMode(const std::string& text, RenderMode* mode);
std::vector<std::string> renderModeNames();  // every name parseRenderMode accepts
const char* compositeOrderName(CompositeOrder order);
bool parseCompositeOrder(const std::string& text, CompositeOrder* order);
std::vector<std::string> compositeOrderNames();  // every name parseCompositeOrder accepts
const char* xrayMapName(XRayMap map);
bool parseXRayMap(const std::string& text, XRayMap* map);
std::vector<std::string> xrayMapNames();  // every name parseXRayMap accepts

enum class PostNormals { Field = 0, Voxel = 1, Ray = 2 };
const char* postNormalsName(PostNormals normals);
bool parsePostNormals(const std::string& text, PostNormals* normals);
std::vector<std::string> postNormalsNames();  // every name parsePostNormals accepts

// How the splat renderer draws a whole composite frame: rasterized slab by slab (points and
// quads blended into slab images), or in compute tiles (TileEwaSplatter: each screen tile's
// slabs added up and classified in one work group; no rasterizer, no blending). Tiles draw
// front-to-back frames (cropped and clipped too), pre-classified or post-classified with four
// samples a slab and field normals, and only frames drawn at once (headless); the rest is
// rasterized. Auto: rasterized where the GPU's timers are not used (software rasterizers, where
// tiles cost many times the rasterized frame); elsewhere the faster as timed frames find it
// (TwoWayTuner: a rasterized frame first, then one in tiles, docs/performance.md "Compute EWA
// splatting"). Cpu: splatted on the CPU in the tiles' shape (CpuSplatter: pixel loops the
// compiler vectorizes, one tile a task over all cores), for machines whose GL is a software
// rasterizer; it draws front-to-back pre-classified composite frames, the rest is rasterized
// (RenderStats::note). Auto does not choose it yet.
enum class Splatter { Raster = 0, Tiles = 1, Auto = 2, Cpu = 3 };
const char* splatterName(Splatter splatter);
bool parseSplatter(const std::string& text, Splatter* splatter);
std::vector<std::string> splatterNames();  // every name parseSplatter accepts

enum class RendererKind { Splat = 0, ShearWarp = 1 };
// Occlusion culling (splats over pixels already opaque are not drawn; the same picture). Auto:
// on hardware GL, off on software rasterizers, where the vertex shader's extra texel fetches
// cost more than they save unless most splats are hidden (docs/performance.md, "Performance").
enum class OcclusionCulling { Auto = 0, On = 1, Off = 2 };
const char* occlusionCullingName(OcclusionCulling mode);
bool parseOcclusionCulling(const std::string& text, OcclusionCulling* mode);
std::vector<std::string> occlusionCullingNames();  // every name parseOcclusionCulling accepts
// Slab images' floats (RenderSettings::slabPrecision): "auto", "half" or "float".
enum class SlabPrecision { Auto = 0, Half = 1, Float = 2 };
const char* slabPrecisionName(SlabPrecision precision);
bool parseSlabPrecision(const std::string& text, SlabPrecision* precision);
std::vector<std::string> slabPrecisionNames();  // every name parseSlabPrecision accepts
// RenderSettings::slabPasses from "auto" (0), "1" or "2"; false for any other text.
bool parseSlabPasses(const std::string& text, int* passes);
std::vector<std::string> slabPassesNames();  // every name parseSlabPasses accepts
const char* slabPassesName(int passes);
// Whether `settings` draw into half-float slab images (the composite mode, by slabPrecision).
struct RenderSettings;
bool halfFloatSlabs(const RenderSettings& settings);
const char* rendererKindName(RendererKind kind);
bool parseRendererKind(const std::string& text, RendererKind* kind);
std::vector<std::string> rendererKindNames();  // every name parseRendererKind accepts

struct RenderSettings {
  RendererKind renderer = RendererKind::Splat;  // which renderer the program creates
  FilterMode filter = FilterMode::Ewa;
  RenderMode mode = RenderMode::Composite;
  // Footprint cutoff r = dx^T Q dx. 5 with kernels 0.7 wide: the narrowest kernel whose lattice
  // ripple stays under 1% (docs/rendering.md, "Kernel width and post-classification"); the paper's
  // 4 at 1.
  double cutoff = 5.0;
  // Kernel standard deviation in voxel spacings per axis (kernelSigma), the mass per voxel
  // unchanged: narrower kernels blur less and cost fewer fragments (as width^2). 0.7: nearer a
  // ray caster close up, cheaper, and the filter-quality findings hold (the paper's is 1).
  double kernelWidth = 0.7;
  // EWA's screen-space low-pass filter: its variance in pixels^2, at most 1 (the paper's); 0:
  // automatic (lowPassVariance): 1 in every mode, so that minified kernels are band-limited
  // pre- and post-classified alike (docs/dev/rendering.md, "Low-pass filter").
  double lowPass = 0.0;
  // Kernels' depth extent in squared standard deviations (at most the cutoff): each kernel's
  // depth profile is cut there (DepthProfile) and it is listed only in the slabs it reaches.
  // Infinite: uncut, listed to the cutoff, the first and last slab taking the tails. 1 (one
  // sigma) lists a kernel in 2 slabs of the default thickness instead of 3: fewer entries, so
  // frames markedly shorter on llvmpipe, pictures within a few levels, nearer thin slabs'
  // (docs/rendering.md, "Depth profile").
  double depthCutoff = 1.0;
  // In units of the smallest voxel spacing, at least 0.25. 2 by default: kernels split exactly
  // between slabs, so thinner slabs change the picture little (tests) and cost more draws.
  double slabThickness = 2.0;
  glm::dvec3 background{0.0};
  CompositeOrder order = CompositeOrder::FrontToBack;
  // Front to back: a pixel stops taking slabs once its opacity reaches this (>= 1: never), and
  // drawing stops once every pixel the volume covers has.
  double terminationOpacity = 0.99;
  // With early termination: splats whose whole screen rectangle lies over pixels already that
  // opaque are not drawn (an opacity pyramid rebuilt with the stencil marks); same picture.
  OcclusionCulling occlusionCulling = OcclusionCulling::Auto;
  XRayMap xrayMap = XRayMap::Attenuation;
  double xrayScale = 1.0;
  Lighting lighting;  // per splat, every frame: the camera moves the light
  // Post-classified by default (nearest a ray caster); gradients and surface voxels. A change
  // rebuilds the splats.
  Classification classification = postClassification();
  // Post-classification only: each pixel's values in two consecutive slabs are classified as a
  // pair through the pre-integration table (a linear ray segment between them), so thin
  // transfer-function peaks between slab values are not missed; off: each slab's mean alone.
  bool slabPreintegration = true;
  // Pre-integrated: each slab's values in depth samples a slab, 2 (its halves) or 4 (its
  // quarters: samples half a voxel apart at the default thickness, where the halves of slabs
  // one voxel thick come nearest a ray caster close up, for fewer draws than such slabs;
  // docs/rendering.md, "Depth samples a slab").
  int slabSamples = 4;
  // Four samples a slab: each slab's kernels splatted once into both of its images (1), or once
  // into each (2): twice the vertex and fragment work for half the blending a pass, the same
  // picture to the bit. On a GPU two passes make some volumes' frames faster and others' slower
  // (docs/performance.md, "On a GPU"); on llvmpipe, whose cost is the fragments, they cost more. 0
  // (auto): one pass where the GPU's timers are not used (software rasterizers); elsewhere the
  // faster as timed frames find it (TwoWayTuner).
  int slabPasses = 0;
  // Composite: slab images of half floats (RGBA16F) or floats. Auto: half floats for kernels
  // at most one spacing wide (the default's 0.7), floats for wider ones, which overlap so many
  // kernels in a pixel of one slab that the smallest contributions round away (a homogeneous
  // medium's opacity 1-4% low at width 1.6), and floats for shaded post-classification with
  // field or voxel normals, whose normals are differences or sums in the slabs (half floats'
  // rounding in field normals moved shaded pixels by up to 7 levels; ray normals, read from the
  // gradient texture, move them by at most 3). Otherwise within a few levels of the floats'
  // pictures (docs/performance.md, "Slab image precision"), while blending half the bytes makes
  // frames much faster on a GPU. X-ray and MIP, whose one image sums or takes the maximum over
  // the whole volume, always use floats.
  SlabPrecision slabPrecision = SlabPrecision::Auto;
  // Post-classified and shaded: each ray segment's normal is the data's gradient read along the
  // pixel's ray at the segment's middle from a 3D texture (Ray, as a ray caster shades; 4
  // bytes a voxel); or each pixel's normal is the gradient of the reconstructed field
  // (Field, pre-integrated only: screen-space differences of the slab's values, the difference
  // of its two halves in depth), or the splats' voxel normals summed in a second image (Voxel;
  // also Field without pre-integration, which has no depth difference). Field and Voxel show
  // the slab period as stripes on smooth surfaces seen obliquely (docs/rendering.md, "Ray
  // normals").
  PostNormals postNormals = PostNormals::Ray;
  Splatter splatter = Splatter::Auto;  // whole composite frames in compute tiles or not
  // Composite: each slab is splatted into an image as coarse as its kernels allow (up to 4
  // pixels a texel a side where every footprint is at least 2 texels wide, so near the eye in
  // magnified views; slab_image_scale.h) and read back bilinearly, classified per pixel; the
  // picture stays within a level or two (docs/rendering.md, "Slab image scale"). False: every slab
  // at the picture's resolution.
  bool coarseSlabs = true;
  double surfaceOpacity = 0.95;  // opacity of the surface-splat layer seen along its normal
  ShearWarpSettings shearWarp;   // read by the shear-warp renderer only
  ClipRegion clip;               // crop box and clipping planes (world space), every renderer
};

// What point (window coordinates, as pickRay takes them) of a width x height picture drawn with
// `settings` shows: through their crop box and clipping planes, the brightest point shown in MIP,
// else the median depth of the pixel's opacity. The one pick of --pick, the window's probe and
// its double-click.
PickResult pickInPicture(const Volume& volume, const TransferFunction& tf,
                         const RenderSettings& settings, const Camera& camera, int width,
                         int height, const glm::dvec2& point);

// The close-up setting, which is also the default: post-classified and pre-integrated between
// slabs, kernels 0.7 spacings wide at cutoff 5 (the narrowest whose lattice ripple stays under
// 1% at any width above it). Measured nearest to a ray caster close up, and cheaper than the
// paper's setting (docs/rendering.md, "Narrower kernels and a thinner margin"). Restores those
// settings over others; surface splats go (post-classification draws none).
void applyCloseUpSettings(RenderSettings* settings);

// The footprint parameters every splat of a volume with this spacing gets under `settings`:
// Swan's s is the smallest spacing, and voxels closer than it to the eye plane are culled.
FootprintParams footprintParams(const RenderSettings& settings, const glm::dvec3& spacing);

// Post-classified splatting: the transfer function applied per pixel (composite mode only;
// X-ray and MIP stay pre-classified).
bool postClassified(const RenderSettings& settings);

// The low-pass filter's variance in pixels^2 under `settings` (RenderSettings::lowPass).
double lowPassVariance(const RenderSettings& settings);

// The kernels' depth profile under `settings`: cut at min(cutoff, depthCutoff), or uncut.
DepthProfile depthProfile(const RenderSettings& settings);

// settings.classification as the splats must be built for these settings: post-classification
// keeps a margin of as many voxels as a kernel reaches (cutoff and kernel width). Pass this, not
// settings.classification, wherever splats are built or compared.
Classification splatClassification(const RenderSettings& settings);

struct RenderStats {
  size_t splatsTotal = 0;  // non-transparent voxels
  size_t splatsDrawn = 0;  // in front of the eye, sent to the GPU this frame
  size_t slabs = 0;
  size_t slabsDrawn = 0;     // before early termination stopped the slab loop
  size_t slabsCoarse = 0;    // of slabsDrawn, those splatted into a coarser image
  size_t surfaceSplats = 0;  // splats drawn as flat surface kernels
  size_t slabEntries = 0;    // splats drawn summed over slabs (kernels span several slabs)
  size_t entriesCulled = 0;  // of slabEntries, those occlusion culling did not rasterize
  bool quadPass = false;     // some footprints exceeded the point-size limit
  // The slab lists came from the GPU's partition, whose order of a slab's entries (and the
  // rounding of their sums with it) may vary between frames; false: the CPU's, or none.
  bool gpuPartition = false;
  bool tiles = false;  // the splat stage ran in compute tiles (RenderSettings::splatter)
  bool cpu = false;    // the splat stage ran on the CPU (Splatter::Cpu)
  // Why the frame was not drawn as asked, in one line (the compute splatter's programs did not
  // build on this GL, so it was rasterized); empty when it was.
  std::string note;
  int slabPasses = 0;  // four samples a slab: the passes each slab took (1 or 2); 0 otherwise
  // Wall time of the last frame (render(), or beginFrame and every stepFrame), waits for the
  // GPU included.
  double renderMs = 0.0;
  // Time per stage of the last frame, for the statistics panel; 0 where a renderer does not
  // measure it (classify: splats from the transfer function, 0 when the set was kept;
  // partition: the slab partition and its upload; splat: drawing the kernels and blending each
  // slab under the image, which interleave per slab; composite: the final pass to the output).
  double classifyMs = 0.0;
  double partitionMs = 0.0;
  double splatMs = 0.0;
  double compositeMs = 0.0;
  // The CPU splatter's part of splatMs (cpu): each splat's footprint and colour, the binning
  // of slab entries to tiles, the tiles' splatting, classification and compositing.
  double cpuRecordsMs = 0.0;
  double cpuBinMs = 0.0;
  double cpuTilesMs = 0.0;
  size_t cpuBytes = 0;  // the CPU splatter's splat records and tile bins at their largest
  size_t gpuBytes = 0;  // bytes of GL buffers and textures the renderer allocated; 0: not counted
};

// Which splatter drew the frame of `stats`: "cpu", "tiles" or "raster" (--stats' `splatter`,
// the window's statistics panel).
const char* splatterUsed(const RenderStats& stats);

class Renderer {
 public:
  virtual ~Renderer() = default;
  // The volume must outlive the renderer or the next setVolume call.
  virtual void setVolume(const Volume& volume) = 0;
  virtual void setTransferFunction(const TransferFunction& tf) = 0;
  // Makes ready what frames of width x height under `settings` will need (shader variants,
  // images, tables), so that their first frame, or a window's first refinement step, does not
  // stall on it. Optional.
  virtual void prepare(const RenderSettings& /*settings*/, int /*width*/, int /*height*/) {}
  // Makes the images a frame of width x height under `settings` draws into, taking about
  // `budgetMs` at most (where the renderer has a worker for it, the images are made there and
  // the call waits for it that long); true once they are all there, so the frame makes none. A
  // frame under way is abandoned where its images change. Renderers without such images: true.
  virtual bool prepareImages(const RenderSettings& /*settings*/, int /*width*/, int /*height*/,
                             double /*budgetMs*/) {
    return true;
  }
  // Renders into the renderer's own output image of width x height pixels.
  virtual void render(const Camera& camera, const RenderSettings& settings, int width,
                      int height) = 0;
  // Progressive drawing, for a window that must keep answering input: beginFrame starts a
  // frame, each stepFrame call draws about `budgetMs` of it and returns true once the frame is
  // complete and outputTexture()/readImage() show it; until then they keep the last complete
  // image (of the size before, where the size changes). frameProgress() is the share drawn so far
  // (0..1). A new beginFrame abandons a frame under way. The defaults draw the whole frame with
  // render() in the first step.
  virtual void beginFrame(const Camera& camera, const RenderSettings& settings, int width,
                          int height);
  virtual bool stepFrame(double budgetMs);
  virtual double frameProgress() const;
  // The last image, top row first, RGB over the background.
  virtual Image8 readImage() const = 0;
  // GL texture name of the last image (RGBA8, bottom row first), for drawing it in a window.
  virtual unsigned outputTexture() const = 0;
  virtual RenderStats stats() const = 0;

 private:
  // The frame the default beginFrame/stepFrame draw.
  struct PendingFrame {
    Camera camera;
    RenderSettings settings;
    int width = 0, height = 0;
  };
  std::optional<PendingFrame> pending_;
};

}  // namespace ewa
