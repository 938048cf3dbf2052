// What every benchmark program shares: main() with one-line errors, the clock, summaries of
// timings, the --backend option and where the shared volumes are.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "core/stopwatch.h"

namespace CLI {
class App;
}

namespace ewa {

// Runs `run(argc, argv)`; an exception becomes "PROGRAM: message" on stderr and exit status 1.
int benchmarkMain(const char* program, int (*run)(int, char**), int argc, char** argv);

using BenchClock = std::chrono::steady_clock;
double secondsSince(BenchClock::time_point start);
// CPU seconds of this process, all threads: less sensitive than wall time to other programs
// loading the machine.
double cpuSeconds();

struct TimingSummary {
  double median = 0.0, min = 0.0, max = 0.0;
};
// Median (the upper one for an even count), minimum and maximum; zeros when empty.
TimingSummary summarize(std::vector<double> values);

// Adds `--backend osmesa|egl` (default osmesa) writing into `backend`.
void addBackendOption(CLI::App& app, std::string& backend);

// ../shared/data beside the source tree: the benchmarks' default volumes.
std::string sharedDataDir();

}  // namespace ewa
