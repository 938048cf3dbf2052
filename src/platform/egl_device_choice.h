// Which EGL device a headless EGL context draws on: EWAVIEW_EGL_DEVICE, or the rank's node-local
// rank where several ranks share a node's GPUs.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ewa::platform {

// `text` as a device index: a whole number from 0, nothing else around it. Throws
// std::invalid_argument naming `what` (the variable or option it came from) otherwise.
int parseEglDeviceIndex(const std::string& text, const std::string& what);

// EWAVIEW_EGL_DEVICE's index (0 is the first device eglQueryDevicesEXT lists), or none when the
// variable is unset or empty. Throws std::invalid_argument naming the variable for a bad value.
std::optional<int> eglDeviceFromEnvironment();

// The device that the rank with node-local rank `localRank` draws on, among devices of which
// `software[i]` says whether device i is a software renderer (EGL_MESA_device_software): the
// node's ranks go round its hardware devices (the k-th hardware device, k = localRank % their
// count), so 8 ranks on a node of 4 GPUs put 2 on each. Mesa lists its software device beside
// the GPUs; it is chosen only where there is no other. -1 when there is no device.
int eglDeviceForLocalRank(int localRank, const std::vector<bool>& software);

// The node-local rank EglContext chooses its device by (eglDeviceForLocalRank), for the whole
// process: a distributed program sets it once before it creates its context. -1 (the default)
// leaves the choice to EglContext's usual order. EWAVIEW_EGL_DEVICE, where set, wins over it.
void setEglLocalRank(int localRank);
int eglLocalRank();

}  // namespace ewa::platform
