// Frame statistics as one JSON line (ewaview --stats, ewaview-compare) and the process's peak
// memory.
#pragma once

#include <cstddef>
#include <string>

#include "render/renderer.h"

namespace ewa {

// The most resident memory this process has held, in bytes (getrusage); 0 when unknown.
size_t peakRssBytes();

// GPU bytes the renderer holds per splat of the volume (splatsTotal): 0 when either is unknown.
double gpuBytesPerSplat(const RenderStats& stats);

// {"renderer":..,"width":..,"height":..,"render_ms":..,"classify_ms":..,"partition_ms":..,
//  "splat_ms":..,"final_ms":..,"splats":..,"splats_drawn":..,"slabs":..,"slab_entries":..,
//  "gpu_bytes":..,"gpu_bytes_per_splat":..,"peak_rss":..}: gpu_bytes_per_splat is null where
// the renderer does not count its GPU memory or draws no splats.
std::string frameStatsJson(const RenderStats& stats, const std::string& renderer, int width,
                           int height);

}  // namespace ewa
