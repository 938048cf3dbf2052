// Fuzz target: the --raw-* option parser and the raw loader. Input lines 1-4 are the dims,
// type, spacing and endian option texts; the first data.N section is the raw file.
#include <string>
#include <vector>

#include "fuzz_case.h"
#include "io/volume_loader.h"
#include "volume_checks.h"

EWA_FUZZ_TARGET(raw) {
  static ewa::fuzz::ScratchFiles files;
  const std::vector<std::string> sections = ewa::fuzz::splitSections(data, size);
  std::vector<std::string> options;
  size_t pos = 0;
  const std::string& head = sections[0];
  for (int i = 0; i < 4; ++i) {
    const size_t eol = head.find('\n', pos);
    options.push_back(head.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos));
    pos = eol == std::string::npos ? head.size() : eol + 1;
  }
  ewa::RawOptions raw;
  try {
    raw = ewa::parseRawOptions(options[0], options[1], options[2], options[3]);
  } catch (const ewa::LoadError& e) {
    EWA_FUZZ_CHECK(std::string(e.what()).rfind("--raw-", 0) == 0);
    return;
  }
  for (int64_t d : raw.dims) EWA_FUZZ_CHECK(d > 0);
  for (int a = 0; a < 3; ++a) EWA_FUZZ_CHECK(raw.spacing[a] > 0.0 && raw.spacing[a] < 1e301);
  files.write(data, size, "in.raw");
  const std::string path = files.folder() + "/data.0";
  try {
    ewa::fuzz::checkVolume(ewa::loadRawVolume(path, raw));
  } catch (const ewa::LoadError& e) {
    EWA_FUZZ_CHECK(std::string(e.what()).rfind(path + ": ", 0) == 0);
  }
}
