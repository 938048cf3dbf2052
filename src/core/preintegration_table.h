// Pre-integration tables: RGBA of a ray segment whose scalar varies linearly from front to back.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "core/transfer_function.h"

namespace ewa {

// Table index i stands for the scalar lo + (hi - lo) * i / (size - 1). Entries hold the
// premultiplied colour c and opacity alpha of a segment `distance` world units long
// (Schulze et al. 2003, Sec. 2.4, with self-attenuation inside the segment):
//   alpha = 1 - exp(-d * int_0^1 tau(s(w)) dw)
//   c     = int_0^1 tau(s(w)) c(s(w)) exp(-d * int_0^w tau(s(w')) dw') d dw,
// s(w) = (1 - w) s_front + w s_back, tau and c from the transfer function (tau per world unit).
class PreintegrationTable {
 public:
  PreintegrationTable() = default;

  // Fast construction, O(size^2 * substeps): each table interval is split into `substeps`
  // sub-bins of constant tau and colour (the sub-bin's mean tau and tau-weighted mean colour,
  // from 8 samples each); a segment from index f to b
  // crosses |b - f| * substeps of them, each over the length d / (|b - f| * substeps), and they
  // are composited front to back with their exact self-attenuation (all segments of one |b - f|
  // from composites of blocks of that many sub-bins). Entries with f == b are
  // exact: alpha = 1 - exp(-tau d), c = colour * alpha. Throws std::invalid_argument for
  // size < 2, substeps < 1, distance <= 0 or non-finite bounds.
  static PreintegrationTable build(const TransferFunction& tf, double lo, double hi, int size,
                                   double distance, int substeps = 4);
  // The same table with each segment's sub-bins composited on their own, O(size^3 * substeps):
  // the check of build()'s blocks (they differ only in rounding).
  static PreintegrationTable buildBySegments(const TransferFunction& tf, double lo, double hi,
                                             int size, double distance, int substeps = 4);

  int size() const { return size_; }
  double distance() const { return distance_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  const glm::vec4& at(int front, int back) const {
    return entries_[size_t(front) * size_t(size_) + size_t(back)];
  }
  // Row-major: entries()[front * size + back].
  const std::vector<glm::vec4>& entries() const { return entries_; }
  // The segment's mean extinction per world unit, int_0^1 tau(s(w)) dw, as the entries take
  // it (the point value for front == back, the sub-bin means between), in double precision:
  // alpha = 1 - exp(-d * meanExtinction) for any length d, also where alpha rounds to 1.
  double meanExtinction(int front, int back) const;

 private:
  enum class Compositing { Blocks, EachSegment };
  static PreintegrationTable buildTable(const TransferFunction& tf, double lo, double hi, int size,
                                        double distance, int substeps, Compositing compositing);

  int size_ = 0, substeps_ = 1;
  double lo_ = 0.0, hi_ = 0.0, distance_ = 1.0;
  std::vector<glm::vec4> entries_;
  std::vector<double> pointTau_;   // tau at each table index
  std::vector<double> tauPrefix_;  // sums of the sub-bins' mean tau, from index 0
};

// Reference: the same integrals for one segment by `steps` midpoint steps along the ray, each
// with its exact exponential attenuation, reading the transfer function itself (no table).
// Returns (premultiplied r, g, b, alpha).
glm::dvec4 integrateSegment(const TransferFunction& tf, double sFront, double sBack,
                            double distance, int steps);

// Point-sample classification for the standard (non-pre-integrated) mode: entry i holds
// (colour * alpha, alpha) with alpha = 1 - exp(-tau(s_i) * distance), the diagonal of the
// pre-integration table.
std::vector<glm::vec4> buildPointTable(const TransferFunction& tf, double lo, double hi, int size,
                                       double distance);

}  // namespace ewa
