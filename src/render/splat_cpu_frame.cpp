// SplatRenderer::drawCpu: the frame begun handed to the CPU splatter (Splatter::Cpu, or auto on
// a software rasterizer), with the CPU partition's slab lists and the splat programs' state as
// C++ (cpuSplatSetup); within a window's budget on a worker thread, so UI frames go on.
#include <string>

#include "core/covered_length.h"
#include "core/stopwatch.h"
#include "render/splat_renderer.h"

namespace ewa {

bool SplatRenderer::cpuWanted(const RenderSettings& settings) const {
  return settings.splatter == Splatter::Cpu || (settings.splatter == Splatter::Auto && softwareGl_);
}

void SplatRenderer::cancelCpu() {
  if (!pendingCpu_.valid()) return;
  cpuCancel_ = true;
  pendingCpu_.wait();
  pendingCpu_ = {};
  cpuCancel_ = false;
  frame_.cpuPending = false;
}

SplatRenderer::CpuStep SplatRenderer::drawCpu(double budgetMs, Clock::time_point stepStart) {
  if (!frame_.cpuPending) {
    if (frame_.gpuSlabs || !volume_ || classified_.splats.size() == 0) return CpuStep::Skipped;
    if (!cpu_) cpu_ = std::make_unique<CpuSplatter>();
    SplatFrameSetup setup = cpuSplatSetup(*volume_, frame_.camera, frame_.proj, frame_.settings,
                                          frame_.reach, transferTable_);
    setup.footprint = cpuFootprint_;
    TileClassifyTables tables;
    tables.pairTexels = pairTable_.texels().data();
    tables.pairSize = SlabPairTable::kSize;
    tables.prefix = pairTable_.prefix().data();
    tables.prefixSize = int(pairTable_.prefix().size());
    tables.transfer = transferTable_.data();
    tables.transferSize = int(transferTable_.size());
    TileCompositeSettings composite =
        cpuCompositeSettings(setup, frame_.settings, tables, cameraToIndex(*volume_, frame_.camera),
                             volume_->indexDataBox());
    composite.flatDepths = cpuFlatDepths_;
    composite.gradients = &gradients_.packed();  // ray normals: held in memory (requestGradients)
    // The inputs are the renderer's and stay unchanged until the work is done or cancelled
    // (cancelCpu, from everything that changes them).
    auto work = [this, setup = std::move(setup), composite = std::move(composite)] {
      return cpu_->compute(classified_, partition_.order(), frame_.slabs, setup, composite,
                           &cpuCancel_);
    };
    if (!std::isfinite(budgetMs)) {
      finishCpu(work(), 0.0);
      return CpuStep::Drawn;
    }
    frame_.cpuStart = Clock::now();
    // A window's frame: in the background arena, so the UI frames keep their time.
    if (!cpuArena_) cpuArena_ = std::make_unique<BackgroundArena>();
    pendingCpu_ = std::async(std::launch::async,
                             [this, work = std::move(work)] { return cpuArena_->execute(work); });
    frame_.cpuPending = true;
  }
  // Waits at most what is left of the step's budget; a picture ready late in it goes up in the
  // next step (its upload and final pass would push this UI frame past its bound).
  const double left = std::min(budgetMs, 1e9) - millisecondsSince(stepStart);
  const auto wait = std::chrono::duration<double, std::milli>(std::max(0.0, left));
  if (pendingCpu_.wait_for(wait) != std::future_status::ready) return CpuStep::Pending;
  if (std::isfinite(budgetMs) && millisecondsSince(stepStart) > 0.5 * budgetMs)
    return CpuStep::Pending;
  frame_.cpuPending = false;
  const CpuSplatter::Timing t = pendingCpu_.get();  // rethrows what the work threw
  finishCpu(t, millisecondsSince(frame_.cpuStart) - t.totalMs());
  return CpuStep::Drawn;
}

void SplatRenderer::finishCpu(const CpuSplatter::Timing& t, double waitedMs) {
  const double uploadMs = cpu_->upload();
  // On a worker the splat stage took the work's wall time (the steps between count it).
  stats_.splatMs += t.totalMs() + uploadMs + std::max(0.0, waitedMs);
  stats_.cpuRecordsMs = t.recordsMs;
  stats_.cpuBinMs = t.binMs;
  stats_.cpuTilesMs = t.compositeMs;
  stats_.cpuBytes = t.bytes;
  stats_.slabEntries = frameEntryCount();
  stats_.slabsDrawn = frame_.slabs.size();
  stats_.slabPasses = 0;
  frame_.cpu = stats_.cpu = true;
}

const std::vector<glm::vec4>& SplatRenderer::cpuPicture() const {
  static const std::vector<glm::vec4> kNone;
  return cpu_ ? cpu_->picture() : kNone;
}

}  // namespace ewa
