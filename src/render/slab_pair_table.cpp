// SlabPairTable: builds the pre-integration texels and uploads them as a linear 2D texture.
#include "render/slab_pair_table.h"

#include <chrono>

#include "core/preintegration_table.h"
#include "core/slab_preintegration.h"
#include "core/stopwatch.h"

namespace ewa {

double SlabPairTable::prepare(const TransferFunction& tf, double lo, double hi, double distance) {
  if (valid_ && lo == lo_ && hi == hi_ && distance == distance_) return 0.0;
  const auto start = std::chrono::steady_clock::now();
  // A constant volume has lo == hi: any range holds its one value at coordinate 0.
  const double top = hi > lo ? hi : lo + 1.0;
  texels_ = slabPairTexels(PreintegrationTable::build(tf, lo, top, kSize, distance), tf);
  if (!texture_) {
    texture_ = gl::Texture::create2D(GL_RGBA32F, kSize, kSize);
    texture_.setFilter(GL_LINEAR, GL_LINEAR);
    texture_.setWrap(GL_CLAMP_TO_EDGE);
  }
  // Row f (texture y) holds the front value f, column b (x) the back value.
  texture_.subImage2D(0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, texels_.data());
  prefixValues_ = extinctionPrefix(tf, lo, top, kExtinctionPrefixSize);
  if (!prefix_) {
    prefix_ = gl::Texture::create2D(GL_R32F, kExtinctionPrefixSize, 1);
    prefix_.setFilter(GL_LINEAR, GL_LINEAR);
    prefix_.setWrap(GL_CLAMP_TO_EDGE);
  }
  prefix_.subImage2D(0, 0, 0, kExtinctionPrefixSize, 1, GL_RED, GL_FLOAT, prefixValues_.data());
  valid_ = true;
  lo_ = lo;
  hi_ = hi;
  distance_ = distance;
  return millisecondsSince(start);
}

size_t SlabPairTable::bytes() const {
  return (texture_ ? size_t(kSize) * kSize * 16 : 0) +
         (prefix_ ? size_t(kExtinctionPrefixSize) * sizeof(float) : 0);
}

}  // namespace ewa
