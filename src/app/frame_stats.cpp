// Frame statistics as JSON: the names the README documents for --stats.
#include "app/frame_stats.h"

#include <sys/resource.h>

#include <algorithm>
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

double cpuBytesPerSplat(const RenderStats& s) {
  return s.splatsTotal > 0 ? double(s.cpuBytes) / double(s.splatsTotal) : 0.0;
}

namespace {

// The names of one renderer's frame (every object of --stats holds them).
void putFrame(const RenderStats& s, nlohmann::ordered_json& j) {
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
  j["splatter"] = splatterUsed(s);
  j["slab_passes"] = s.slabPasses;
  if (s.cpu) {
    j["cpu_records_ms"] = s.cpuRecordsMs;
    j["cpu_bin_ms"] = s.cpuBinMs;
    j["cpu_tiles_ms"] = s.cpuTilesMs;
    j["cpu_bytes_per_splat"] = cpuBytesPerSplat(s);
  }
  j["gpu_bytes"] = s.gpuBytes;
  const double perSplat = gpuBytesPerSplat(s);
  j["gpu_bytes_per_splat"] = perSplat > 0.0 ? nlohmann::ordered_json(perSplat) : nullptr;
}

RenderStats summed(const std::vector<RenderStats>& channels) {
  RenderStats t;
  for (const RenderStats& s : channels) {
    t.splatsTotal += s.splatsTotal;
    t.splatsDrawn += s.splatsDrawn;
    t.slabs += s.slabs;
    t.slabsDrawn += s.slabsDrawn;
    t.slabsCoarse += s.slabsCoarse;
    t.surfaceSplats += s.surfaceSplats;
    t.slabEntries += s.slabEntries;
    t.entriesCulled += s.entriesCulled;
    t.quadPass |= s.quadPass;
    t.gpuPartition |= s.gpuPartition;
    t.tiles |= s.tiles;
    t.cpu |= s.cpu;
    if (!s.note.empty()) t.note += (t.note.empty() ? "" : "; ") + s.note;
    t.slabPasses = std::max(t.slabPasses, s.slabPasses);
    t.renderMs += s.renderMs;
    t.classifyMs += s.classifyMs;
    t.partitionMs += s.partitionMs;
    t.splatMs += s.splatMs;
    t.compositeMs += s.compositeMs;
    t.cpuRecordsMs += s.cpuRecordsMs;
    t.cpuBinMs += s.cpuBinMs;
    t.cpuTilesMs += s.cpuTilesMs;
    t.cpuBytes += s.cpuBytes;
    t.gpuBytes += s.gpuBytes;
  }
  return t;
}

}  // namespace

std::string frameStatsJson(const RenderStats& s, const std::string& renderer, int width,
                           int height) {
  return frameStatsJson(std::vector<RenderStats>{s}, renderer, width, height);
}

std::string frameStatsJson(const std::vector<RenderStats>& channels, const std::string& renderer,
                           int width, int height) {
  const RenderStats s = summed(channels);
  nlohmann::ordered_json j;
  j["renderer"] = renderer;
  j["width"] = width;
  j["height"] = height;
  putFrame(s, j);
  j["peak_rss"] = peakRssBytes();
  j["huge_pages"] = hugePagesInUse();
  if (!s.note.empty()) j["note"] = s.note;
  if (channels.size() > 1) {
    nlohmann::ordered_json each = nlohmann::ordered_json::array();
    for (const RenderStats& c : channels) {
      nlohmann::ordered_json one;
      putFrame(c, one);
      if (!c.note.empty()) one["note"] = c.note;
      each.push_back(one);
    }
    j["channels"] = each;
  }
  return j.dump();
}

}  // namespace ewa
