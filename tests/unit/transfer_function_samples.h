// Transfer functions shared by the pre-integration tests.
#pragma once

#include "core/transfer_function.h"

namespace ewa::test {

// Over values 0..255: transparent except a thin opaque peak at 100 (two intervals of a
// 256-entry table wide).
inline TransferFunction thinPeakTf() {
  TransferFunction tf;
  tf.opacity = {{0.0, 0.0}, {99.0, 0.0}, {100.0, 0.95}, {101.0, 0.0}, {255.0, 0.0}};
  tf.color = {{0.0, {1.0, 1.0, 1.0}}, {100.0, {0.9, 0.2, 0.1}}, {255.0, {0.0, 0.0, 1.0}}};
  tf.opacityUnitDistance = 0.5;
  return tf;
}

}  // namespace ewa::test
