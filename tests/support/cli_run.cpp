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

std::filesystem::path brokenShaders(const std::filesystem::path& dir, const std::string& file,
                                    const std::string& from, const std::string& to) {
  namespace fs = std::filesystem;
  const fs::path shaders = dir / "shaders";
  fs::create_directories(dir);
  if (!fs::exists(shaders)) fs::copy(EWA_SOURCE_SHADER_DIR, shaders);
  std::string text = readWholeFile(shaders / file);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << file;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::ofstream(shaders / file, std::ios::binary | std::ios::trunc) << text;
  return shaders;
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
