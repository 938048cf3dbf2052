// SplatRenderer::drawCpu: the frame begun handed to the CPU splatter (Splatter::Cpu), with the
// CPU partition's slab lists and the splat programs' state as C++ (cpuSplatSetup).
#include <string>

#include "core/covered_length.h"
#include "render/splat_renderer.h"

namespace ewa {

bool SplatRenderer::drawCpu() {
  std::string why;
  if (!cpuSplatterDraws(frame_.settings, &why)) {
    stats_.note = why;
    return false;
  }
  if (frame_.gpuSlabs || !volume_ || classified_.splats.size() == 0) return false;
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
  const CpuSplatter::Timing t = cpu_->draw(
      classified_, partition_.order(), frame_.slabs, setup, frame_.settings, tables,
      cameraToIndex(*volume_, frame_.camera), volume_->indexDataBox(), true, cpuFlatDepths_);
  stats_.cpuRecordsMs = t.recordsMs;
  stats_.cpuBinMs = t.binMs;
  stats_.cpuTilesMs = t.compositeMs;
  stats_.slabEntries = frameEntryCount();
  stats_.slabsDrawn = frame_.slabs.size();
  stats_.slabPasses = 0;
  frame_.cpu = stats_.cpu = true;
  return true;
}

const std::vector<glm::vec4>& SplatRenderer::cpuPicture() const {
  static const std::vector<glm::vec4> kNone;
  return cpu_ ? cpu_->picture() : kNone;
}

}  // namespace ewa
