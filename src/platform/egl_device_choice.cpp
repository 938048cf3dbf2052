// EGL device choice: the EWAVIEW_EGL_DEVICE variable and the device for a node-local rank.
#include "platform/egl_device_choice.h"

#include <atomic>
#include <cstdlib>
#include <stdexcept>

namespace ewa::platform {

namespace {

// Atomic: set by the program's main thread, read where a context is created (an upload thread
// may create one too).
std::atomic<int> gLocalRank{-1};

}  // namespace

int parseEglDeviceIndex(const std::string& text, const std::string& what) {
  // Digits only: std::stoi would take " 1", "+1" and "1x", which hide a typing slip.
  bool digits = !text.empty() && text.size() <= 6;
  for (char c : text) digits = digits && c >= '0' && c <= '9';
  if (!digits)
    throw std::invalid_argument(what + "=\"" + text +
                                "\": expected an EGL device index (0 for the first device)");
  return std::stoi(text);
}

std::optional<int> eglDeviceFromEnvironment() {
  const char* value = std::getenv("EWAVIEW_EGL_DEVICE");
  if (!value || !*value) return std::nullopt;
  return parseEglDeviceIndex(value, "EWAVIEW_EGL_DEVICE");
}

int eglDeviceForLocalRank(int localRank, const std::vector<bool>& software) {
  if (software.empty()) return -1;
  std::vector<int> hardware;
  for (size_t i = 0; i < software.size(); ++i)
    if (!software[i]) hardware.push_back(int(i));
  const int rank = localRank < 0 ? 0 : localRank;
  if (hardware.empty()) return rank % int(software.size());
  return hardware[size_t(rank) % hardware.size()];
}

void setEglLocalRank(int localRank) {
  gLocalRank = localRank < 0 ? -1 : localRank;
}

int eglLocalRank() {
  return gLocalRank;
}

}  // namespace ewa::platform
