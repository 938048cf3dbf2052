// FrameDescription: what one distributed frame needs (camera, settings, transfer function, size),
// and its byte form, which the window's rank broadcasts to the others every frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "core/transfer_function.h"
#include "render/renderer.h"

namespace ewa {

struct FrameDescription {
  // A frame to draw, or the end: every rank leaves its loop with `exitStatus`.
  bool quit = false;
  int exitStatus = 0;
  Camera camera;
  RenderSettings settings;  // the clip region in world space, as every rank's volume sits
  TransferFunction tf;
  int width = 0, height = 0;
};

// The description as bytes (host byte order: the ranks of one run share a machine type).
std::vector<uint8_t> serializeFrame(const FrameDescription& frame);
// The description `bytes` hold; throws std::runtime_error when they are cut short, carry another
// version or leave bytes over.
FrameDescription deserializeFrame(const uint8_t* bytes, size_t size);

}  // namespace ewa
