// The render tests' command-line runner: std::system with captured output and a timeout.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "image_compare.h"

namespace ewa::test {

std::string readWholeFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

int lineCount(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

CliRun runEwaview(const std::string& args, const std::string& prefix, int timeoutSeconds) {
  return runProgram(EWA_BINARY, args, prefix, timeoutSeconds);
}

CliRun runProgram(const std::string& binary, const std::string& args, const std::string& prefix,
                  int timeoutSeconds) {
  const std::string stem = testOutputDir() + "/" + prefix + "_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string cmd = "timeout " + std::to_string(timeoutSeconds) + " " + binary + " " + args +
                          " >" + stem + ".out 2>" + stem + ".err </dev/null";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readWholeFile(stem + ".out");
  r.err = readWholeFile(stem + ".err");
  return r;
}

int runToRunLevels(const std::string& statsLine) {
  return nlohmann::json::parse(statsLine).value("gpu_partition", false) ? kGpuPartitionLevels : 0;
}

}  // namespace ewa::test
