// Test files written by Debian's python3 (zarr, numcodecs, h5py) at test time: the interpreter
// the build names (EWA_PYTHON), whose Debian modules the tests compare against.
#pragma once

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace ewa::testing {

// "" when EWA_PYTHON imports `modules` ("zarr, numcodecs"), else why not: the tests skip with
// it (and fail with it when CI=true).
inline std::string pythonLacks(const std::string& modules) {
  const std::string python = EWA_PYTHON;
  if (std::system((python + " -c 'import " + modules + "' >/dev/null 2>&1").c_str()) == 0)
    return "";
  return python + " cannot import " + modules + " (Debian: python3-zarr, python3-h5py)";
}

// Runs `script` with `folder` as its argument; "" on success, else its output.
inline std::string runPython(const std::string& script, const std::string& folder) {
  const std::string file = folder + "/make_fixtures.py", log = folder + "/make_fixtures.log";
  std::ofstream(file) << script;
  if (std::system(
          (std::string(EWA_PYTHON) + " " + file + " " + folder + " >" + log + " 2>&1").c_str()) ==
      0)
    return "";
  std::ifstream in(log);
  return "the fixture script failed: " + std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace ewa::testing
