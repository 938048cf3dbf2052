// Frame statistics as JSON: the names the README documents for --stats.
#include "app/frame_stats.h"

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "app/heap_tuning.h"

namespace ewa {

size_t peakRssBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return size_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

double gpuBytesPerSplat(const RenderStats& s) {
  return s.gpuBytes > 0 && s.splatsTotal > 0 ? double(s.gpuBytes) / double(s.splatsTotal) : 0.0;
}

std::string frameStatsJson(const RenderStats& s, const std::string& renderer, int width,
                           int height) {
  nlohmann::ordered_json j;
  j["renderer"] = renderer;
  j["width"] = width;
  j["height"] = height;
  j["render_ms"] = s.renderMs;
  j["classify_ms"] = s.classifyMs;
  j["partition_ms"] = s.partitionMs;
  j["splat_ms"] = s.splatMs;
  j["final_ms"] = s.compositeMs;
  j["splats"] = s.splatsTotal;
  j["splats_drawn"] = s.splatsDrawn;
  j["slabs"] = s.slabs;
  j["slabs_drawn"] = s.slabsDrawn;
  j["slab_entries"] = s.slabEntries;
  j["entries_culled"] = s.entriesCulled;
  j["slabs_coarse"] = s.slabsCoarse;
  j["gpu_partition"] = s.gpuPartition;
  j["splatter"] = s.tiles ? "tiles" : "raster";
  j["slab_passes"] = s.slabPasses;
  j["gpu_bytes"] = s.gpuBytes;
  const double perSplat = gpuBytesPerSplat(s);
  j["gpu_bytes_per_splat"] = perSplat > 0.0 ? nlohmann::ordered_json(perSplat) : nullptr;
  j["peak_rss"] = peakRssBytes();
  j["huge_pages"] = hugePagesInUse();
  if (!s.note.empty()) j["note"] = s.note;
  return j.dump();
}

}  // namespace ewa
