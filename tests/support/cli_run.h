// Runs the ewaview program as a user does and captures its exit status and output: the one
// command-line runner of the render tests.
#pragma once

#include <filesystem>
#include <string>

namespace ewa::test {

struct CliRun {
  int code = -1;  // exit status; -1 when killed by a signal
  std::string out, err;
};

// Runs `EWA_BINARY args` (args as a shell would split them) with stdin closed, stopped after
// `timeoutSeconds` (a hung program fails the test instead of hanging CTest). Output is captured
// in files named `prefix_TESTNAME` in the test output folder, since CTest runs tests in parallel.
CliRun runEwaview(const std::string& args, const std::string& prefix = "cli",
                  int timeoutSeconds = 300);
// The same for another program of the project (a benchmark) at `binary`.
CliRun runProgram(const std::string& binary, const std::string& args, const std::string& prefix,
                  int timeoutSeconds = 300);

// Whole file as a string ("" when it cannot be read).
std::string readWholeFile(const std::string& path);

// A copy of the source tree's shaders/ in `dir`/shaders (made once) with the text `from` in
// `file` replaced by `to`, for --shader-dir or a gl::ShaderLibrary; returns that folder.
std::filesystem::path brokenShaders(const std::filesystem::path& dir, const std::string& file,
                                    const std::string& from, const std::string& to);

// Number of '\n' in `s`: errors must be one line.
int lineCount(const std::string& s);

// The levels (of 255) two runs' pictures of one setting may differ by, from a run's --stats
// line: 0 where the CPU's slab partition drew it, kGpuPartitionLevels where the GPU's did.
int runToRunLevels(const std::string& statsLine);

}  // namespace ewa::test
