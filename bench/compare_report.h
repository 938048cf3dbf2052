// The comparison benchmark's results: one row per volume and image size, printed as a table,
// CSV or JSON.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace ewa {

// Milliseconds are medians over the timed repeats; negative: not measured.
struct CompareRow {
  std::string volume;
  std::string dims;  // "256x256x128"
  int size = 0;      // width = height
  size_t splats = 0, splatsDrawn = 0;
  size_t slabEntries = 0, entriesCulled = 0;  // EWA's splat draws, and those occlusion culled
  double ewaMs = -1, ewaMinMs = -1;
  double partitionMs = -1, splatMs = -1, finalMs = -1;  // EWA's stages (RenderStats)
  double spritesMs = -1, shearWarpMs = -1, vtkCpuMs = -1, vtkGpuMs = -1;
  // The same footprints added up by compute tiles (TileSplatBaseline): in all, and the binning.
  double tilesMs = -1, tilesBinMs = -1;
  // The same frame splatted by compute tiles, slab by slab (TileEwaSplatter): its records,
  // binning and compositing; measured where the tiles draw the frame's settings
  // (SplatRenderer::tileComposite: front to back, post-classified only pre-integrated in
  // quarters).
  double tileEwaMs = -1;
  // The same frame splatted on the CPU (Splatter::Cpu), and its stages: the slab partition, each
  // splat's record (footprint and colour), the binning to tiles, the tiles' splatting,
  // classification and compositing.
  double cpuMs = -1;
  double cpuPartitionMs = -1, cpuRecordsMs = -1, cpuBinMs = -1, cpuTilesMs = -1;
  double cpuBytesPerSplat = -1;  // the CPU splatter's records and tile bins
  size_t gpuBytes = 0;           // 0: the renderer does not count it
  double gpuBytesPerSplat = 0;
  size_t peakRss = 0;  // of the benchmark process after this row

  // EWA's full frame over the other method's frame; negative when either is missing.
  double ratio(double otherMs) const { return ewaMs > 0 && otherMs > 0 ? ewaMs / otherMs : -1; }
  // The CPU splatter's frame over VTK's CPU ray caster's; negative when either is missing.
  double cpuPerVtkCpu() const { return cpuMs > 0 && vtkCpuMs > 0 ? cpuMs / vtkCpuMs : -1; }
};

struct CompareReport {
  std::string context;  // the GL context's description
  std::string command;  // the command line that made it
  int repeats = 0;
  std::string ewaSettings;         // "kernel width 1.00, pre-classification"
  std::vector<std::string> notes;  // "cthead skipped: ...", "VTK not timed: ..."
  std::vector<CompareRow> rows;
};

enum class ReportFormat { Table, Csv, Json };

// Table: a header of '#' lines, then aligned columns; CSV: one header line and a line per
// row; JSON: one document {"context","command","repeats","ewa_settings","notes","rows":[{...}]},
// with null for what was not measured.
void printReport(std::ostream& out, const CompareReport& report, ReportFormat format);

}  // namespace ewa
