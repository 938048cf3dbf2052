// The benchmark programs' shared main(), clock, timing summaries and options.
#include "bench/bench_support.h"

#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <exception>
#include <iostream>

#include "app/heap_tuning.h"
#include "app/option_binding.h"
#include "app/options.h"
#include "platform/headless_context.h"

namespace ewa {

int benchmarkMain(const char* program, int (*run)(int, char**), int argc, char** argv) {
  if (const std::string nan = optionWithNan(argc, argv); !nan.empty()) {
    std::cerr << program << ": " << nan << ": not a finite number (see --help)\n";
    return 2;
  }
  askForHugePages(argv);  // as ewaview itself runs
  keepFreedHeapForReuse();
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

double secondsSince(BenchClock::time_point start) {
  return std::chrono::duration<double>(BenchClock::now() - start).count();
}

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

TimingSummary summarize(std::vector<double> values) {
  if (values.empty()) return {};
  std::sort(values.begin(), values.end());
  return {values[values.size() / 2], values.front(), values.back()};
}

void addBackendOption(CLI::App& app, std::string& backend) {
  backend = platform::defaultHeadlessBackend();
  addTableOption(app, "--backend", backend);
}

std::string sharedDataDir() {
  return std::string(EWA_ASSET_DIR) + "/../../shared/data";
}

}  // namespace ewa
