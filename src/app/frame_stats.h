// Frame statistics as one JSON line (ewaview --stats, ewaview-compare) and the process's peak
// memory.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "render/renderer.h"

namespace ewa {

// The most resident memory this process has held, in bytes (getrusage); 0 when unknown.
size_t peakRssBytes();

// GPU bytes the renderer holds per splat of the volume (splatsTotal): 0 when either is unknown.
double gpuBytesPerSplat(const RenderStats& stats);
// The CPU splatter's record and bin bytes per splat of the volume: 0 when no splats.
double cpuBytesPerSplat(const RenderStats& stats);

// {"renderer":..,"width":..,"height":..,"render_ms":..,"classify_ms":..,"partition_ms":..,
//  "splat_ms":..,"final_ms":..,"splats":..,"splats_drawn":..,"slabs":..,"slab_entries":..,
//  "gpu_bytes":..,"gpu_bytes_per_splat":..,"peak_rss":..}: gpu_bytes_per_splat is null where
// the renderer does not count its GPU memory or draws no splats.
std::string frameStatsJson(const RenderStats& stats, const std::string& renderer, int width,
                           int height);
// One frame of overlaid channels, each drawn by its own renderer: one channel's as above; more
// than one: the channels' sums (times, counts, bytes; a flag where any has it, the most slab
// passes, the notes joined) in the same names, and "channels", an array of each channel's own
// statistics under the same names (without renderer, width, height, peak_rss, huge_pages).
std::string frameStatsJson(const std::vector<RenderStats>& channels, const std::string& renderer,
                           int width, int height);

}  // namespace ewa
