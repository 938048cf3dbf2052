// SplatRenderer: EWA (and Swan and plain) volume splatting with image-aligned slab compositing.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <utility>

#include "core/background_arena.h"
#include "core/slab_image_scale.h"
#include "core/slab_partition.h"
#include "core/slab_rect.h"
#include "core/splat_attributes.h"
#include "core/splat_set.h"
#include "core/step_cost_model.h"
#include "core/two_way_tuner.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/shader_library.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/cpu_splatter.h"
#include "render/gpu_slab_partition.h"
#include "render/gradient_texture.h"
#include "render/occlusion_pyramid.h"
#include "render/order_pages.h"
#include "render/render_targets.h"
#include "render/renderer.h"
#include "render/slab_pair_table.h"
#include "render/slab_pass_programs.h"
#include "render/splat_program_set.h"
#include "render/splat_programs.h"
#include "render/splat_upload.h"
#include "render/tile_ewa_splatter.h"

namespace ewa {

// Where the per-frame slab partition is built: GPU compute passes (gpu_slab_partition.h) or the
// CPU (SlabPartition, plus the order list's upload). Auto: measured faster (docs/performance.md,
// "Performance"): the CPU on software rasterizers (llvmpipe, softpipe), the GPU elsewhere.
enum class PartitionMode { Auto = 0, Gpu = 1, Cpu = 2 };
const char* partitionModeName(PartitionMode mode);
bool parsePartitionMode(const std::string& text, PartitionMode* mode);

class SplatRenderer : public Renderer {
 public:
  // Builds the shader programs; a GL 4.5 context must be current. Throws gl::GlError.
  // `programs`: a set shared with other renderers of this context (made here when null).
  explicit SplatRenderer(const gl::ShaderLibrary& shaders,
                         std::shared_ptr<SplatProgramSet> programs = nullptr);
  ~SplatRenderer() override;

  // Post-classified, shaded and pre-integrated with PostNormals::Field: the slab pass takes
  // each pixel's normal from the field's gradient (no voxel normals read or summed).
  static bool fieldNormals(const RenderSettings& settings);
  // Post-classified and shaded with PostNormals::Ray: the slab pass reads each segment's normal
  // from the gradient texture along the pixel's ray (no voxel normals read or summed).
  static bool rayNormals(const RenderSettings& settings);

  void setVolume(const Volume& volume) override;
  void setTransferFunction(const TransferFunction& tf) override;
  // Compiles the splat and slab-pass programs of `settings`' variant (and the coarser slab
  // pass's where coarse slabs are on), allocates the images and builds the pre-integration
  // tables, as beginFrame would (on llvmpipe the images or the tables alone can cost more than a
  // UI frame's budget).
  void prepare(const RenderSettings& settings, int width, int height) override;
  // On a worker bound to the upload context where there is one (RenderTargets::prepare).
  bool prepareImages(const RenderSettings& settings, int width, int height,
                     double budgetMs) override;
  using Clock = std::chrono::steady_clock;

  // render() = beginFrame + stepFrame(infinity): the whole frame at once.
  void render(const Camera& camera, const RenderSettings& settings, int width, int height) override;
  // Classification (when due), the slab partition and its upload, the per-frame uniforms. The
  // images of a new size are made by the steps, as many a step as its budget holds;
  // readImage() and outputTexture() keep the last finished picture, of the size before, until
  // the frame is done.
  void beginFrame(const Camera& camera, const RenderSettings& settings, int width,
                  int height) override;
  // Draws slabs in chunks, timing each (glFinish) and sizing the next from the measured cost
  // per splat entry, until `budgetMs` would be passed; the last step runs the final pass.
  bool stepFrame(double budgetMs) override;
  double frameProgress() const override;
  Image8 readImage() const override;
  unsigned outputTexture() const override { return targets_.shownOutput().id(); }
  // The last frame's figures; gpuBytes: the buffers and textures allocated now.
  RenderStats stats() const override;

  // Live transfer-function editing (kept apart from the drawing code): uploads `tf`'s table to
  // the GPU now and keeps the current splats, so the next render shows the new colours and
  // opacities without classifying the volume again. Voxels the new function makes visible
  // appear once a matching set comes through setSplats(). Needs setVolume() first.
  void updateTransferTexture(const TransferFunction& tf);
  // Replaces the splats with a set classified elsewhere (e.g. AsyncSplatBuilder) for the
  // current volume under `classification` and uploads it; the next render draws it (and does
  // not classify again unless the settings ask for another classification).
  void setSplats(ClassifiedSplats splats, const Classification& classification);
  // A context of this renderer's share group (outliving it, or null): big splat sets
  // (beginSplats) and a stepped frame's images of a new size (RenderTargets::prepare) are then
  // made on a worker bound to it.
  void setUploadContext(platform::UploadContext* uploads) { uploads_ = uploads; }
  // setSplats without holding this thread for a big set: with an upload context, a set of
  // kWorkerUploadBytes or more (setWorkerUploadBytes) is uploaded into a new buffer by a worker
  // (SplatUpload) while frames draw the set before, and is put in place by a later
  // takeUploadedSplats(), or by the next beginFrame() under its classification (which waits for
  // it). Else the set is set at once. True when the set is in place now. Another set, volume,
  // function or classification drops the one being uploaded.
  bool beginSplats(ClassifiedSplats splats, const Classification& classification);
  // Puts the set beginSplats() is uploading in place once the upload is done; true when it did.
  // Throws what the upload threw (the set before stays).
  bool takeUploadedSplats();
  bool uploadingSplats() const { return upload_ != nullptr; }
  static constexpr size_t kWorkerUploadBytes = size_t(4) << 20;  // 0.5 M splats
  // Test hook: sets of this many bytes or more go to the worker (default kWorkerUploadBytes).
  void setWorkerUploadBytes(size_t bytes) { workerUploadBytes_ = bytes; }
  // True when the next frame under `classification` would classify the volume itself (no set
  // for the current volume, function and classification is there or being uploaded).
  bool needsSplats(const Classification& classification) const {
    if (upload_ && upload_->classification() == classification) return false;
    return volume_ && (splatsDirty_ || classification != classification_);
  }
  // Chooses where the slab partition is built (Auto by default); takes effect next frame.
  void setPartition(PartitionMode mode) { partitionMode_ = mode; }
  // True when frames build the partition on the GPU (Auto resolved for this GL).
  bool gpuPartition() const;
  // True when `mode` culls occluded splats on this GL (Auto: not on software rasterizers).
  bool occlusionCulling(OcclusionCulling mode) const {
    return mode == OcclusionCulling::On || (mode == OcclusionCulling::Auto && !softwareGl_);
  }

  // Program variants compiled so far, splat and slab pass (tests).
  size_t programsCompiled() const { return splatPrograms_.compiled() + slabPrograms_.compiled(); }

  // The most splats the GL buffers may hold: pass it to a classification made elsewhere.
  size_t maxSplats() const { return maxSplats_; }

  // X-ray mode only: the summed optical depth per pixel, bottom row first (for tests).
  std::vector<float> readOpticalDepth() const;
  // What the last frame's final pass turned into the picture, before the background: RGBA
  // floats per pixel, bottom row first. Composite: premultiplied colour and opacity (the
  // rasterizer's, the tiles' or the CPU's picture); X-ray: the summed optical depth in alpha;
  // MIP: the maximum in red. Distributed rendering composites these across ranks (src/dist).
  std::vector<float> readFramePicture() const;
  // Anchors the slab grid at camera depth `depth` (DepthExtent::anchorDepth) from the next
  // frame on; NaN (the default) anchors it at the nearest kernel. A distributed run sets the
  // same anchor on every rank so that bricks cut the slabs the whole volume would.
  void setSlabAnchor(double depth) { slabAnchor_ = depth; }
  // The splats of the current volume and transfer function (built on the next render()).
  const SplatSet& splats() const { return classified_.splats; }
  const AttributeList& attributes() const { return classified_.attributes; }
  // The largest point size this GL draws; bigger footprints go through the quad path.
  float pointSizeLimit() const { return pointSizeLimit_; }
  // Test hook: a lower limit forces the quad path (never above the GL limit).
  void setPointSizeLimit(float limit);
  // Test hook: fewer splats allowed than the GL limit, to test the error without a huge volume.
  void setMaxSplats(size_t maxSplats) { maxSplats_ = std::min(glMaxSplats_, maxSplats); }
  // Test hook: a smaller storage block than the GL's, so that small volumes take the paths of
  // huge ones (splats in texel buffers, the order list bound in windows); 0: the GL's.
  void setStorageBlockLimit(uint64_t bytes) { storageBlockLimit_ = bytes; }
  // Test hook: the most entries a page of the CPU partition's order list holds (default
  // OrderPages::kDefaultPageEntries); a budgeted frame uploads the list a page at a time. A new
  // size drops the pages.
  void setOrderUploadPiece(size_t entries) { orderPages_.setPageEntries(entries); }
  // Test hook: pages of the CPU partition's order list in the last frame's layout.
  size_t orderPageCount() const { return orderPages_.pages(); }
  // True when frames read the splats from texel buffers: they exceed a storage block.
  bool texelBuffers() const;
  // Test hook: in X-ray mode, sum only each kernel's share between these camera depths (the
  // share one composite slab gets, without open tails). nullopt: the whole kernel.
  void setDepthWindow(std::optional<std::pair<double, double>> window) { depthWindow_ = window; }
  // Test hook: limit each slab's splats, composite and mark passes to the rectangle its
  // kernels can reach (slab_rect.h; on by default), or draw them over the whole image.
  void setSlabScissor(bool on) { slabScissor_ = on; }
  // Early termination reads its occlusion query without waiting (lagged by one check; the
  // default on hardware GL) or waits for it (the default on software rasterizers, where the
  // wait costs nothing: the CPU draws everything anyway). Lagged, while the CPU has no answer
  // the slabs after a check are drawn under conditional rendering on the check before: a GPU,
  // which runs behind the CPU, skips them once that check found nothing left to draw.
  void setLaggedTermination(bool lagged) { laggedTermination_ = lagged; }
  bool laggedTermination() const { return laggedTermination_; }
  // A whole frame's stage times (splats, final pass) from GPU timestamps (glQueryCounter),
  // without waiting for the splats before the final pass is queued (the default on hardware
  // GL); or from the CPU's clock around a glFinish after each stage (the default on software
  // rasterizers, which draw everything when it is waited for anyway). Budgeted steps time
  // their chunks with glFinish either way: the next chunk is sized from the last one's time.
  void setGpuTimers(bool on) { gpuTimers_ = on; }
  // Test hook: whether auto takes the GL for a software rasterizer, and so splats on the CPU
  // (cpuWanted); found from GL_RENDERER at construction.
  void setSoftwareRasterizer(bool software) { softwareGl_ = software; }
  // Test hook: with two splat passes a slab, each pass leaves out the kernels whose cut depth
  // profile misses its half of the slab (on by default; the picture is the same either way).
  void setPassHalfCulling(bool on) { passHalfCulling_ = on; }
  // Splatter auto draws in tiles only up to this many splats: their records, lists and images
  // take about 250 GPU bytes a splat against the rasterizer's 16-30 (docs/performance.md, "Compute
  // EWA splatting"), 2 GB at this count; bigger volumes keep the rasterizer's memory.
  static constexpr size_t kAutoTileSplats = 8'000'000;
  // Test hook: another limit than kAutoTileSplats.
  void setAutoTileSplats(size_t splats) { autoTileSplats_ = splats; }
  // A budgeted frame (the window's refinement) is drawn whole in tiles in one step where auto
  // chooses them and their last frame here, at the cost a slab entry it took, would take at
  // most this long: a UI frame under the 100 ms the window keeps to. Before the tiles' first
  // frame here they are tried (on a GPU they can cost a small part of the rasterizer's time).
  static constexpr double kTileStepMs = 80.0;
  // Test hooks: another limit than kTileStepMs; the auto splatter's costs.
  void setTileStepMs(double ms) { tileStepMs_ = ms; }
  TwoWayTuner& splatterTuner() { return splatterTuner_; }
  TwoWayTuner& passTuner() { return passTuner_; }
  bool gpuTimers() const { return gpuTimers_; }
  // GL_RENDERER names a software rasterizer (llvmpipe, softpipe): what the auto modes go by.
  bool softwareGl() const { return softwareGl_; }
  // The compute splatter's records of the last frame begun (TileEwaSplat, tile_ewa_splatter.h:
  // four vec4 a splat in splats() order, zeros for a splat not drawn), made on the GPU as the
  // splat vertex shaders make each footprint (shaders/tile_ewa_footprints.comp.glsl), into
  // `out`, which must hold splats().size() records.
  void writeTileSplats(gl::Buffer& out);
  // Whether the compute splatter draws the last frame begun: front to back (clipped or not) and
  // pre-classified, or post-classified, pre-integrated in quarters of a slab, shaded (if at
  // all) from the field's gradient; and the TileEwaFrame flags (post, shading) that say how.
  bool tileComposite(bool& post, bool& shading) const;
  // The splats' compute-tile records (64 bytes each) fit one storage block (storageBlockBytes):
  // the tiles read them as one; past its end they read nothing.
  bool tileRecordsFit() const;
  // The GPU partition of the last frame begun, if it built its slab lists on the GPU (the
  // compute splatter can bin them where they are: TileEwaSplatter::useGpuSlabLists).
  const GpuSlabPartition* gpuSlabLists() const {
    return frame_.gpuSlabs ? gpuPartition_.get() : nullptr;
  }
  // Hands the last frame begun to `tiles` for its next draw (TileEwaSplatter::setFrame and the
  // rest): its slab lists (the CPU partition's, or the GPU's where it built them there:
  // gpuSlabLists), the records (writeTileSplats) and the composite's uniforms and textures
  // (prepareTileComposite). False, and nothing handed over, where the tiles do not draw the
  // frame (tileComposite) or it has no splats.
  bool loadTiles(TileEwaSplatter& tiles);
  // Test hook: the footprint the CPU splatter (Splatter::Cpu) gives each splat
  // (computeFootprint by default), to show a wrong one fails its tests.
  void setCpuFootprint(FootprintFunction footprint) { cpuFootprint_ = std::move(footprint); }
  // Test hook: the CPU splatter's slab split made wrong (TileCompositeSettings::flatDepths).
  void setCpuFlatDepths(bool flat) { cpuFlatDepths_ = flat; }
  // The CPU splatter's picture of the last frame it drew (premultiplied, rows bottom up).
  const std::vector<glm::vec4>& cpuPicture() const;

 private:
  void rebuildSplats(const Classification& classification);
  void uploadTransferTexture();
  void uploadSplats();
  // Throws GlError when `count` splats are more than the order entries can index.
  static void checkSplatCount(size_t count);
  // The splat set of upload_ in place of the current one (waits for the upload; throws its
  // error, the current set kept).
  void installUpload();
  // What a new splat buffer leaves stale: the order list's pages, the attributes.
  void splatBufferReplaced();
  // Uploads the attributes (8 bytes a splat) when a frame under `settings` reads them (shading
  // or surface splats), else frees them; attributesUploaded_ says which.
  void syncAttributes(const RenderSettings& settings);
  void setCommonUniforms(gl::Program& program, const Camera& camera, const Projection& proj,
                         const RenderSettings& settings);
  // The image the splats are drawn into: focal length, pixels per unit, size, principal point
  // and EWA's low-pass variance in its pixels.
  void setProjectionUniforms(gl::Program& program, const Projection& proj, double lowPass) const;
  // Pixels the splat viewport reaches beyond `image` on every side (drawSplats): the largest
  // point's radius, less where GL_MAX_VIEWPORT_DIMS leaves no room.
  int guardBand(const Projection& image) const;
  // slabIndex >= 0: the GPU partition's slab (its first entry and draw commands on the GPU).
  void setSlabUniforms(const Slab& slab, bool split, bool openTails, int slabIndex = -1);
  // Post-classification (composite mode only): splats carry values, the slab pass classifies.
  static bool postClassified(const RenderSettings& settings);
  // Makes the gradients ready for frames under `settings` that read them (a texture for the
  // slab pass, in memory for the CPU splatter; packed on a worker) unless they are, and frees
  // them otherwise; returns whether a frame must wait for them.
  bool requestGradients(const RenderSettings& settings);
  // Post-classified and pre-integrated between slabs: two slab images, drawn in turn.
  static bool pairedSlabs(const RenderSettings& settings);
  // Coarser slab images may be drawn: their marks need a depth image of their own.
  static bool coarseMarks(const RenderSettings& settings);
  // The images a frame of width x height under `settings` draws into.
  static TargetLayout targetLayout(const RenderSettings& settings, int width, int height);
  // Paired slabs with four depth samples a slab (RenderSettings::slabSamples): a second image
  // a slab for its back half.
  static bool quarterSlabs(const RenderSettings& settings);
  // The passes a slab of a frame with `settings` takes: the setting's, or auto's choice.
  int slabPassesFor(const RenderSettings& settings) const;
  // The slabs' thickness in world units for a volume of this spacing seen through a camera of
  // this rotation (viewSpacing).
  static double slabThickness(const RenderSettings& settings, const glm::dvec3& spacing,
                              const glm::dmat3& rotation);
  // Builds the pre-integration tables for `settings` and slabs of `thickness` unless they are
  // up to date; returns the milliseconds it took (0 when nothing was built).
  double preparePairTable(const RenderSettings& settings, double thickness);
  // Post-classified and shaded from voxel normals: splats sum them into the normal image.
  static bool voxelNormalSums(const RenderSettings& settings);
  // The splat programs' variant for `settings` (clip: the volume is cut; texel buffers: the
  // splats exceed a storage block), and the slab pass's (scaled: it reads a coarser image).
  SplatVariant splatVariant(const RenderSettings& settings, bool texelBuffers) const;
  SlabPassVariant slabPassVariant(const RenderSettings& settings, bool scaled) const;
  // The slab pass's uniforms and the slab buffer's draw buffers for this frame.
  void setSlabPassUniforms(const Projection& proj, const RenderSettings& settings);
  // Its classification's: the camera's, the light's, the data's box and the pair table's units.
  void setClassifyUniforms(gl::Program& p, const Projection& proj, const RenderSettings& settings);
  // Draws the slab's splats into the bound image at frame_.splatScale, through the guard band.
  void drawSplats(const Slab& slab, bool quads, int slabIndex = -1);
  void drawSplatPrimitives(const Slab& slab, bool quads, int slabIndex);
  // The GPU partition's per-slab counts, read back: its empty slabs dropped, drawn like the
  // CPU's from then on (for drawing in budgeted steps and for the statistics).
  void takeGpuCounts();
  void setFrameWeights();
  // Selects this frame's program variants and sets their per-frame uniforms (programs_->user).
  void setFrameUniforms();
  // Draws the whole frame in compute tiles (RenderSettings::splatter) if it can: false, and
  // nothing drawn, where tileComposite says the tiles do not draw these settings.
  bool drawTiles();
  bool drawTilesNow();  // drawTiles, failures thrown
  // Whether the frame's splats go to the CPU splatter: asked for (Splatter::Cpu), or auto on a
  // software rasterizer, where it is many times faster than rasterizing the kernels.
  bool cpuWanted(const RenderSettings& settings) const;
  // Draws the whole frame on the CPU (Drawn), or Skipped where there is nothing to draw or the
  // GPU partition has the frame's lists. Within a budget
  // (a window's step, begun at `stepStart`) the work runs on a worker thread and steps return
  // Pending, after waiting at most what is left of `budgetMs`, until it is done.
  enum class CpuStep { Drawn, Skipped, Pending };
  CpuStep drawCpu(double budgetMs, Clock::time_point stepStart);
  // Stops a CPU frame under way and waits for it (its inputs are about to change); the next
  // step starts it again.
  void cancelCpu();
  // The CPU frame's picture uploaded and its figures in the statistics; `waitedMs`: the wall
  // time of a worker's frame beyond its own stages.
  void finishCpu(const CpuSplatter::Timing& t, double waitedMs);
  // The compute splatter's programs, in the set this renderer may share (SplatProgramSet).
  const std::shared_ptr<TileEwaPrograms>& tilePrograms();
  // Sets the crop box's and clipping planes' uniforms and, post-classified, the
  // classification's uniforms and textures (the slab pass's: the pair table, the data's box,
  // the light) of the last frame begun on the compute splatter's composite `program`
  // (TileEwaSplatter::compositeProgram), for its next draw.
  void prepareTileComposite(gl::Program& program);
  // Splatter auto may draw frames under `settings` in tiles: the GPU's timers are used, the
  // tiles' programs built and the volume within the splat limit.
  bool autoTiles(const RenderSettings& settings) const;
  // Whether a whole frame under `settings` is drawn in tiles if they draw it (splatter: Tiles,
  // or Auto's choice where autoTiles).
  bool tilesWanted(const RenderSettings& settings) const;
  // Whether tiles may draw the frame in a step of `budgetMs` (infinite: a whole frame), from
  // the slabs' counts known by then (kTileStepMs).
  bool tilesFitStep(double budgetMs) const;
  // Auto splatter, at a frame's end: this frame's splat stage a slab entry of the whole frame
  // (GPU timers for a whole frame; the steps' own clock, their waits included, for a budgeted
  // one), for the way it took (frames the tiles do not draw are not counted); the note of tiles
  // that failed to build.
  void reportSplatterCost();
  // The slab entries of every slab of the frame (frame_.slabs), drawn or not.
  size_t frameEntryCount() const;
  // GL state every step needs again (a window draws other things between steps).
  void bindFrameState();
  void setSlabLoopState();
  // Front to back with a termination opacity below 1: the stencil marks opaque pixels.
  bool terminates() const;
  // One slab of the front-to-back or back-to-front loop (index in drawing order): its images
  // cleared (begin), its splats (drawSlabRange: entries [first, first + count) of them, in one
  // or more ranges), the blend under (over) the image and, every few slabs, the
  // early-termination check (passSlabRows and closeSlab: the slab's finish).
  void beginCompositeSlab(size_t slabIndex);
  // Which slab image (RenderTargets::slabImage) slab `slabIndex` of the drawing order sums
  // into: alternating with paired slabs, else 0.
  int slabImageOf(size_t slabIndex) const;
  // Clip-space z of the mark slab `slabIndex` (in drawing order) leaves in the depth buffer
  // where its splats reach, rising from slab to slab by slabMarkStep (passSlabRows).
  float slabMark(size_t slabIndex) const;
  float slabMarkStep() const;
  // Each slab's rectangle and image scale (frame_.slabRects, frame_.slabScales, in
  // frame_.slabs order) for this frame's slabs.
  void computeSlabRects();
  // The image scale of slab `slabIndex` of the drawing order (1 without computeSlabRects).
  double slabScale(size_t slabIndex) const;
  // Sets the splat programs' projection, low-pass filter, clip rays and occlusion culling for
  // an image `scale` times coarser than the picture (1: the picture), and the viewport.
  void setSplatScale(double scale);
  // The slab pass program for slab `slabIndex` of the drawing order: the variant that reads
  // coarser images where it or its neighbour has one.
  gl::Program& slabPassProgram(size_t slabIndex);
  // The frame's slabs are known: statistics, the splat programs' variant and uniforms.
  void prepareSlabs(double nearestCenter);
  // The CPU partition's result (waits for the worker): order upload (with `budgeted`, a big
  // list only allocated, its entries left to uploadOrderPieces), slabs, prepareSlabs.
  void takeCpuPartition(bool budgeted);
  // Copies pieces of the order list until it is all up (true) or the budget is spent.
  bool uploadOrderPieces(double budgetMs, Clock::time_point start);
  // The final pass's expected milliseconds a row of this frame (its last price a pixel).
  double finalRowMs() const;
  // The frame's images cleared (the whole images: accumulation, slab, marks).
  void clearTargets();
  // Makes the frame's images still missing within `budgetMs`, then clears them; true once done.
  bool prepareTargets(double budgetMs);
  // Returns once no partition is running on the worker thread.
  void waitForPartition();
  // Scissor to the rectangle of slab `slabIndex` (drawing order), when slab scissors are on.
  void scissorToSlab(size_t slabIndex, double scale = 1.0);
  // Carries a coarser slab's marks (targets_.coarseMarks) to the picture's pixels in the
  // stencil image's depth, each pixel taking its nearest texel's, for its slab pass.
  void blitCoarseMarks(size_t slabIndex);
  // Scissor to `rect` (enables the scissor test).
  static void scissorTo(const PixelRect& rect);
  void drawSlabRange(size_t slabIndex, size_t first, size_t count);
  // Whether this frame's slabs are scissored to their rectangles (setSlabScissor, and the
  // rectangles made for these slabs).
  bool slabRectsInUse() const;
  // The pixels slab `slabIndex`'s pass covers: its rectangle (the whole image without slab
  // scissors).
  PixelRect slabPassRect(size_t slabIndex) const;
  // The slab's composite pass over rows [y0, y1) of its rectangle (the window's steps pass a
  // big slab in bands); every row of the rectangle once, then closeSlab.
  void passSlabRows(size_t slabIndex, int y0, int y1);
  // The slab's statistics and, every few slabs, the opacity marks and termination check.
  void closeSlab(size_t slabIndex);
  // Whether finishing slab `slabIndex` also marks the opaque pixels and checks for early
  // termination (every few slabs, front to back).
  bool finishChecks(size_t slabIndex) const;
  const Slab& slabInOrder(size_t slabIndex) const;
  // Where slab `slabIndex` of the drawing order sits in frame_.slabs.
  size_t slabPosition(size_t slabIndex) const;
  // Return true once the frame's splats are all drawn (or early termination ended it).
  bool drawSlabChunks(double budgetMs, Clock::time_point start);
  bool drawWholeVolumeChunks(double budgetMs, Clock::time_point start);
  // The final pass over rows [y0, y1) of the picture (all of them: the frame's last image).
  void drawFinalPass(int y0, int y1);
  // Starts an occlusion query in `query` counting the pixels of the volume's bounding box not
  // yet marked opaque whose rays still cross what the clip keeps of it at or behind depth
  // `nextDepth` (the next slab's front); false when the box is too near the eye for the test
  // to be safe.
  bool issueOpaqueQuery(unsigned query, double nextDepth);
  // True when the slab loop may stop: every pixel the slabs from depth `nextDepth` on could
  // still reach is marked opaque. Blocking: this check's query is waited for. Lagged: the
  // query of the check before, if its result has come (no wait; the GPU keeps drawing, and
  // stopping up to one check later than possible only draws slabs the stencil rejects anyway,
  // so the picture is the same).
  bool terminationCheck(double nextDepth);
  // Ends the conditional rendering a lagged termination check began, if any.
  void endConditionalSlabs();

  const Volume* volume_ = nullptr;
  TransferFunction tf_;
  bool splatsDirty_ = true;
  Classification classification_;
  ClassifiedSplats classified_;
  SlabPartition partition_;
  double slabAnchor_ = NAN;  // setSlabAnchor
  PartitionMode partitionMode_ = PartitionMode::Auto;
  bool softwareGl_ = false;                            // GL_RENDERER names a software rasterizer
  std::unique_ptr<GpuSlabPartition> gpuPartition_;     // made on first use
  std::unique_ptr<TileEwaSplatter> tiles_;             // RenderSettings::splatter; on first use
  std::unique_ptr<CpuSplatter> cpu_;                   // Splatter::Cpu; on first use
  FootprintFunction cpuFootprint_ = computeFootprint;  // setCpuFootprint
  bool cpuFlatDepths_ = false;                         // setCpuFlatDepths
  std::vector<glm::vec4> transferTable_;  // the transfer texture's table, for the CPU splatter
  gl::ShaderLibrary shaders_;             // for the GPU partition, built on first use
  std::optional<std::pair<double, double>> depthWindow_;
  bool slabScissor_ = true;

  std::shared_ptr<SplatProgramSet> programs_;  // perhaps shared (SplatProgramSet)
  SplatPrograms& splatPrograms_;    // the point and quad programs of this frame's variant
  SlabPassPrograms& slabPrograms_;  // the slab pass of this frame's variants
  gl::Program* slabPass_[2] = {nullptr, nullptr};  // this frame's: full-resolution, coarser
  gl::Program& markProgram_;
  gl::Program& finalProgram_;
  gl::Program& boxProgram_;
  OcclusionPyramid occlusion_;
  static constexpr unsigned kOpaqueUnit = 4;  // texture unit of the occlusion pyramid
  SlabPairTable pairTable_;                   // post-classification with pre-integration
  static constexpr unsigned kPairTableUnit = 5;
  static constexpr unsigned kNeighbourSlabUnit = 6;   // paired slabs: the slab drawn before
  static constexpr unsigned kPairPrefixUnit = 9;      // paired slabs: the extinction prefix
  static constexpr unsigned kSlabBackUnit = 10;       // quarters: the slab's back half
  static constexpr unsigned kNeighbourBackUnit = 11;  // quarters: the neighbour's back half
  GradientTexture gradients_;                         // ray normals: the data's gradient
  static constexpr unsigned kGradientUnit = 12;
  gl::VertexArray emptyVao_;
  gl::Buffer splatBuffer_;
  platform::UploadContext* uploads_ = nullptr;  // setUploadContext
  std::unique_ptr<SplatUpload> upload_;         // a set beginSplats() is uploading, or null
  size_t workerUploadBytes_ = kWorkerUploadBytes;
  OrderPages orderPages_;  // the CPU partition's order list (the GPU's keeps its own)
  gl::Buffer attributeBuffer_;
  bool attributesUploaded_ = false;  // attributeBuffer_ holds classified_.attributes
  gl::Texture transferTexture_;
  RenderTargets targets_;
  size_t glMaxSplats_ = SIZE_MAX;      // splats the GPU's texel buffers and memory hold
  size_t maxSplats_ = SIZE_MAX;        // the limit in force (lower in tests)
  uint64_t maxStorageBlockBytes_ = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  uint64_t storageBlockLimit_ = 0;     // test hook: a lower block size (0: the GL's)
  uint64_t storageAlignment_ = 256;    // GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT
  uint64_t maxTexelBufferTexels_ = 0;  // GL_MAX_TEXTURE_BUFFER_SIZE
  gl::Texture splatTexels_;            // texel-buffer views of splatBuffer_ and attributeBuffer_
  gl::Texture attributeTexels_;
  static constexpr unsigned kSplatTexelUnit = 7;
  static constexpr unsigned kAttributeTexelUnit = 8;
  // The storage block size in force: the GL's, or the test hook's.
  uint64_t storageBlockBytes() const;
  // Draws order entries [first, first + count) of the frame's partition, binding the order list
  // from the first entry in windows a storage block holds, within one page of the CPU's list.
  void drawOrderRange(GLenum mode, bool instanced, size_t first, size_t count);
  unsigned queries_[2] = {0, 0};  // early termination's occlusion queries, used in turn
  bool laggedTermination_ = false;
  // Timestamps of a whole frame: splat stage begun, splat stage done, final pass done.
  unsigned timers_[3] = {0, 0, 0};
  bool gpuTimers_ = false;
  bool passHalfCulling_ = true;  // setPassHalfCulling
  TwoWayTuner passTuner_;        // slabPasses auto: one pass a slab (way 0) or two (way 1)
  unsigned passWaysDrawn_ = 0;   // bit w: a frame drew way w (its first use paid for)
  // Splatter auto: rasterized (way 0) or in tiles (way 1), the tiles tried first: on a GPU
  // they draw the default frames in a small part of the rasterizer's time, so a single picture (and
  // the window's first refinement) takes them.
  TwoWayTuner splatterTuner_{1};
  // The compute splatter's programs failed to build on this GL: auto rasterizes from then on,
  // its frames' RenderStats::note saying why (tilesNote_).
  bool tilesFailed_ = false;
  std::string tilesNote_;
  size_t autoTileSplats_ = kAutoTileSplats;  // setAutoTileSplats
  double tileStepMs_ = kTileStepMs;          // setTileStepMs
  float pointSizeLimit_ = 64.0f;
  float glPointSizeLimit_ = 64.0f;
  int maxViewport_ = 16384;  // GL_MAX_VIEWPORT_DIMS, the smaller
  RenderStats stats_;

  // The frame under way, from beginFrame to the step that draws the final pass.
  struct FrameState {
    bool active = false;      // begun and not finished
    bool drawSplats = false;  // something to draw before the final pass
    Camera camera;
    Projection proj;
    RenderSettings settings;
    int width = 0, height = 0;
    // Of this frame's kernels: the partition, slab rectangles, termination box and quad test.
    KernelReach reach;
    bool texelBuffers = false;         // splats read from texel buffers (texelBuffers())
    double fragmentsPerEntry = 1.0;    // the largest footprint's square, in pixels (budgets)
    bool partitionPending = false;     // the CPU partition runs on pendingPartition_
    bool orderUploading = false;       // the CPU order list is going up in pieces
    size_t orderUploaded = 0;          // pages of it copied so far
    Clock::time_point partitionStart;  // for stats_.partitionMs
    std::vector<Slab> slabs;           // front to back: the CPU partition's, or the GPU's
    std::vector<PixelRect> slabRects;  // per slab: the pixels its kernels can reach
    std::vector<double> slabScales;    // per slab: its image's scale (slab_image_scale.h)
    double splatScale = 1.0;           // the scale the splat programs are set up for
    bool pyramidBuilt = false;         // occlusion culling: a pyramid of this frame is bound
    PixelRect markRect;                // slabs composited since the last opacity marks
    bool gpuSlabs = false;             // slabs come from gpuPartition_
    bool tiles = false;                // drawn in compute tiles: the picture is tiles_'s
    bool cpu = false;                  // drawn on the CPU: the picture is cpu_'s
    bool cpuFrame = false;             // meant for the CPU splatter (cpuWanted)
    bool cpuPending = false;           // its work runs on pendingCpu_
    Clock::time_point cpuStart;        // when that work began
    bool tilesFirstUse = false;        // tiles: programs compiled or the splatter made for it
    bool indirect = false;          // GPU slabs whose counts only the GPU knows (empty ones kept)
    size_t nextSlab = 0;            // composite: the next slab in drawing order
    bool finishPending = false;     // composite: nextSlab's entries are drawn, its finish not
    int passRow = 0;                // composite, finish pending: the next row of its pass
    bool terminated = false;        // early termination ended the slab loop
    bool occlusion = false;         // occlusion culling in this frame (front to back, terminating)
    bool gradientsPending = false;  // ray normals: the gradient texture is still being built
    bool slabsDone = false;         // the slab loop is drawn: the final pass is left
    int finalRow = 0;               // budgeted: the final pass's next row (bands)
    double finalWeight = 0.0;       // the final pass's share of totalWeight
    TargetLayout targetLayout;      // the images this frame draws into
    bool targetsPending = false;    // some of them still to be made (prepareTargets)
    bool pairedSlabs = false;       // post-classified with pre-integration: two slab images
    bool quarters = false;          // paired, four depth samples a slab: two images a slab
    int slabPasses = 1;             // quarters: splat passes a slab (RenderSettings::slabPasses)
    int nextQuery = 0;              // of queries_, the one the next check issues
    bool queryIssued[2] = {false, false};  // lagged termination: a result not yet read
    bool conditional = false;              // lagged termination: conditional rendering begun
    size_t nextEntry = 0;                  // X-ray and MIP: the next entry of the single slab
    double meanEntries = 0.0;              // per slab: the weight of a slab's whole-image passes
    double drawnWeight = 0.0, totalWeight = 0.0;  // for frameProgress()
    bool timed = false;  // the stage times come from timers_ (setGpuTimers)
  };
  FrameState frame_;
  std::future<void> pendingPartition_;           // the CPU partition of frame_ on a worker thread
  std::future<CpuSplatter::Timing> pendingCpu_;  // the CPU splatter's frame on a worker thread
  std::atomic<bool> cpuCancel_{false};           // tells pendingCpu_ to stop
  std::unique_ptr<BackgroundArena> cpuArena_;    // where pendingCpu_'s loops run; on first use
  // Measured, kept across frames: what budgeted steps' entries and slab finishes cost.
  StepCostModel stepCost_;
  glm::dmat3 lastRotation_{1.0};  // the last frame's camera rotation (slabThickness)
  double finalMsPerPixel_ = 0.0;  // the last final pass timed by its wait (not by GPU timers)
};

}  // namespace ewa
