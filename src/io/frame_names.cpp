// Output image names: turntable patterns and folders, timestamped screenshots.
#include "io/frame_names.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace ewa {

namespace {

bool endsWithPng(const std::string& s) {
  if (s.size() < 4) return false;
  std::string ext = s.substr(s.size() - 4);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

// File-name-safe version of a volume name: letters, digits, '-', '_' and '.'.
std::string safeStem(const std::string& name) {
  std::string stem = std::filesystem::path(name).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return stem.empty() ? std::string("volume") : stem;
}

}  // namespace

FrameNaming parseFrameNaming(const std::string& output) {
  if (output.empty()) throw std::invalid_argument("--output: empty");
  if (output.find('%') == std::string::npos) return {false, output};
  int conversions = 0;
  for (size_t i = 0; i < output.size(); ++i) {
    if (output[i] != '%') continue;
    if (i + 1 < output.size() && output[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t j = i + 1;
    if (j < output.size() && output[j] == '0') ++j;
    while (j < output.size() && std::isdigit(static_cast<unsigned char>(output[j]))) ++j;
    if (j >= output.size() || output[j] != 'd' || j - i > 4)
      throw std::invalid_argument(output + ": a turntable pattern takes %d or %0Nd only");
    ++conversions;
    i = j;
  }
  if (conversions != 1)
    throw std::invalid_argument(output + ": a turntable pattern needs exactly one %d");
  if (!endsWithPng(output))
    throw std::invalid_argument(output + ": a turntable pattern must end in .png");
  return {true, output};
}

std::string frameFileName(const FrameNaming& naming, int index, int count) {
  if (naming.pattern) {
    char buffer[4096];
    const int n = std::snprintf(buffer, sizeof buffer, naming.text.c_str(), index);
    if (n < 0 || size_t(n) >= sizeof buffer)
      throw std::invalid_argument(naming.text + ": file name too long");
    return buffer;
  }
  int digits = 3;
  for (int c = count - 1; c >= 1000; c /= 10) ++digits;
  char name[64];
  std::snprintf(name, sizeof name, "frame_%0*d.png", digits, index);
  return (std::filesystem::path(naming.text) / name).string();
}

std::string screenshotFileName(const std::string& dir, const std::string& volumeName,
                               std::time_t when,
                               const std::function<bool(const std::string&)>& taken) {
  std::tm local{};
  localtime_r(&when, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  return unusedFileName(dir, "ewaview-" + safeStem(volumeName) + "-" + stamp, ".png", taken);
}

std::string unusedFileName(const std::string& dir, const std::string& base,
                           const std::string& extension,
                           const std::function<bool(const std::string&)>& taken) {
  const std::filesystem::path folder(dir.empty() ? "." : dir);
  std::filesystem::path path = folder / (base + extension);
  const auto used = [&](const std::filesystem::path& p) {
    return std::filesystem::exists(p) || (taken && taken(p.string()));
  };
  for (int n = 2; used(path) && n < 10000; ++n)
    path = folder / (base + "-" + std::to_string(n) + extension);
  return path.string();
}

}  // namespace ewa
