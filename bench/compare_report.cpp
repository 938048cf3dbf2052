// The comparison benchmark's three output formats, with the same columns in each.
#include "bench/compare_report.h"

#include <cstdio>
#include <nlohmann/json.hpp>

namespace ewa {
namespace {

struct Column {
  const char* name;  // table header
  const char* key;   // CSV and JSON
  double (*value)(const CompareRow&);
  const char* format;  // printf for the table
};

// Every number a row holds, in table order; negative values are "not measured".
const std::vector<Column>& columns() {
  static const std::vector<Column> c = {
      {"splats", "splats", [](const CompareRow& r) { return double(r.splats); }, "%10.0f"},
      {"ewa_ms", "ewa_ms", [](const CompareRow& r) { return r.ewaMs; }, "%9.1f"},
      {"ewa_min_ms", "ewa_min_ms", [](const CompareRow& r) { return r.ewaMinMs; }, "%10.1f"},
      {"partition_ms", "partition_ms", [](const CompareRow& r) { return r.partitionMs; }, "%12.1f"},
      {"splat_ms", "splat_ms", [](const CompareRow& r) { return r.splatMs; }, "%9.1f"},
      {"final_ms", "final_ms", [](const CompareRow& r) { return r.finalMs; }, "%8.1f"},
      {"sprites_ms", "sprites_ms", [](const CompareRow& r) { return r.spritesMs; }, "%10.1f"},
      {"tiles_ms", "tiles_ms", [](const CompareRow& r) { return r.tilesMs; }, "%8.1f"},
      {"tile_bin_ms", "tile_bin_ms", [](const CompareRow& r) { return r.tilesBinMs; }, "%11.1f"},
      {"tile_ewa_ms", "tile_ewa_ms", [](const CompareRow& r) { return r.tileEwaMs; }, "%11.1f"},
      {"cpu_ms", "cpu_ms", [](const CompareRow& r) { return r.cpuMs; }, "%8.1f"},
      {"cpu_part_ms", "cpu_partition_ms", [](const CompareRow& r) { return r.cpuPartitionMs; },
       "%11.1f"},
      {"cpu_rec_ms", "cpu_records_ms", [](const CompareRow& r) { return r.cpuRecordsMs; },
       "%10.1f"},
      {"cpu_bin_ms", "cpu_bin_ms", [](const CompareRow& r) { return r.cpuBinMs; }, "%10.1f"},
      {"cpu_tiles_ms", "cpu_tiles_ms", [](const CompareRow& r) { return r.cpuTilesMs; }, "%12.1f"},
      {"cpu_B/splat", "cpu_bytes_per_splat", [](const CompareRow& r) { return r.cpuBytesPerSplat; },
       "%11.1f"},
      {"shearwarp_ms", "shearwarp_ms", [](const CompareRow& r) { return r.shearWarpMs; }, "%12.1f"},
      {"vtk_cpu_ms", "vtk_cpu_ms", [](const CompareRow& r) { return r.vtkCpuMs; }, "%10.1f"},
      {"vtk_gpu_ms", "vtk_gpu_ms", [](const CompareRow& r) { return r.vtkGpuMs; }, "%10.1f"},
      {"ewa/vtk_cpu", "ewa_per_vtk_cpu", [](const CompareRow& r) { return r.ratio(r.vtkCpuMs); },
       "%11.2f"},
      {"cpu/vtk_cpu", "cpu_per_vtk_cpu", [](const CompareRow& r) { return r.cpuPerVtkCpu(); },
       "%11.2f"},
      {"ewa/sprites", "ewa_per_sprites", [](const CompareRow& r) { return r.ratio(r.spritesMs); },
       "%11.2f"},
      {"culled_%", "culled_percent",
       [](const CompareRow& r) {
         return r.slabEntries > 0 ? 100.0 * double(r.entriesCulled) / double(r.slabEntries) : -1;
       },
       "%8.1f"},
      {"gpu_B/splat", "gpu_bytes_per_splat",
       [](const CompareRow& r) { return r.gpuBytesPerSplat > 0 ? r.gpuBytesPerSplat : -1; },
       "%11.1f"},
      {"peak_rss_MiB", "peak_rss_mib",
       [](const CompareRow& r) { return double(r.peakRss) / (1024.0 * 1024.0); }, "%12.0f"},
  };
  return c;
}

void printTable(std::ostream& out, const CompareReport& r) {
  out << "# " << r.context << "\n# " << r.command << "\n# median of " << r.repeats
      << " frames after a warm-up frame; ms per frame; '-': not measured\n# EWA: " << r.ewaSettings
      << "\n";
  for (const std::string& note : r.notes) out << "# " << note << "\n";
  char cell[64];
  std::snprintf(cell, sizeof cell, "%-18s %5s", "volume", "size");
  out << cell;
  for (const Column& c : columns()) {
    // Each header as wide as its column's numbers.
    int width = 0;
    std::sscanf(c.format + 1, "%d", &width);
    std::snprintf(cell, sizeof cell, " %*s", width, c.name);
    out << cell;
  }
  out << "\n";
  for (const CompareRow& row : r.rows) {
    std::snprintf(cell, sizeof cell, "%-18s %5d", row.volume.c_str(), row.size);
    out << cell;
    for (const Column& c : columns()) {
      const double v = c.value(row);
      int width = 0;
      std::sscanf(c.format + 1, "%d", &width);
      if (v < 0)
        std::snprintf(cell, sizeof cell, " %*s", width, "-");
      else {
        cell[0] = ' ';
        std::snprintf(cell + 1, sizeof cell - 1, c.format, v);
      }
      out << cell;
    }
    out << "\n";
  }
}

void printCsv(std::ostream& out, const CompareReport& r) {
  out << "volume,dims,size";
  for (const Column& c : columns()) out << "," << c.key;
  out << "\n";
  for (const CompareRow& row : r.rows) {
    out << row.volume << "," << row.dims << "," << row.size;
    for (const Column& c : columns()) {
      const double v = c.value(row);
      out << ",";
      if (v >= 0) out << v;
    }
    out << "\n";
  }
}

void printJson(std::ostream& out, const CompareReport& r) {
  nlohmann::ordered_json doc;
  doc["context"] = r.context;
  doc["command"] = r.command;
  doc["repeats"] = r.repeats;
  doc["ewa_settings"] = r.ewaSettings;
  doc["notes"] = r.notes;
  doc["rows"] = nlohmann::ordered_json::array();
  for (const CompareRow& row : r.rows) {
    nlohmann::ordered_json j;
    j["volume"] = row.volume;
    j["dims"] = row.dims;
    j["size"] = row.size;
    for (const Column& c : columns()) {
      const double v = c.value(row);
      if (v < 0)
        j[c.key] = nullptr;
      else if (std::string(c.key) == "splats")
        j[c.key] = row.splats;  // a count, not a measurement
      else
        j[c.key] = v;
    }
    j["splats_drawn"] = row.splatsDrawn;
    j["gpu_bytes"] = row.gpuBytes;
    doc["rows"].push_back(j);
  }
  out << doc.dump(1) << "\n";
}

}  // namespace

void printReport(std::ostream& out, const CompareReport& report, ReportFormat format) {
  switch (format) {
    case ReportFormat::Table:
      printTable(out, report);
      break;
    case ReportFormat::Csv:
      printCsv(out, report);
      break;
    case ReportFormat::Json:
      printJson(out, report);
      break;
  }
  out.flush();
}

}  // namespace ewa
