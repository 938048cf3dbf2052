// Pre-integration tables: fast sub-bin construction and the fine numerical reference.
#include "core/preintegration_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/parallel_chunks.h"

namespace ewa {

namespace {

// Samples of the transfer function inside each sub-bin for its means.
constexpr int kSamplesPerSubBin = 8;

double scalarOf(double lo, double hi, int size, double index) {
  return lo + (hi - lo) * index / double(size - 1);
}

void checkArguments(double lo, double hi, int size, double distance) {
  if (size < 2) throw std::invalid_argument("pre-integration table: size must be at least 2");
  if (!std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("pre-integration table: scalar range must be finite");
  if (!(distance > 0.0) || !std::isfinite(distance))
    throw std::invalid_argument("pre-integration table: segment length must be positive");
}

// A run of sub-bins composited front to back: premultiplied colour and transmittance.
struct Span {
  glm::dvec3 c{0.0};
  double t = 1.0;
};

// `front` in front of `back`.
Span over(const Span& front, const Span& back) {
  return {front.c + front.t * back.c, front.t * back.t};
}

glm::vec4 entry(const Span& s) {
  return glm::vec4(float(s.c.r), float(s.c.g), float(s.c.b), float(1.0 - s.t));
}

// Sub-bins begin .. begin + count - 1 in increasing order, one by one.
Span compositeUp(const std::vector<Span>& bin, int begin, int count) {
  Span s;
  for (int m = 0; m < count; ++m) s = over(s, bin[size_t(begin + m)]);
  return s;
}

// The same sub-bins in decreasing order.
Span compositeDown(const std::vector<Span>& bin, int begin, int count) {
  Span s;
  for (int m = count - 1; m >= 0; --m) s = over(s, bin[size_t(begin + m)]);
  return s;
}

// Every window of `count` consecutive sub-bins from one diagonal's partial composites in
// blocks of `count` (a window is the tail of one block over the head of the next), so a
// diagonal costs O(bins) instead of O(bins * count); "over" is associative, so only the
// rounding differs from compositing each window alone.
class SpanBlocks {
 public:
  void build(const std::vector<Span>& bin, int count) {
    const int n = int(bin.size());
    count_ = count;
    for (auto* v : {&upHead_, &upTail_, &downHead_, &downTail_}) v->resize(size_t(n));
    for (int j = 0; j < n; ++j) {
      const bool first = j % count == 0;  // the first sub-bin of its block
      // Heads: the block's start .. j, increasing (up) and decreasing (down) order.
      upHead_[j] = first ? bin[j] : over(upHead_[j - 1], bin[j]);
      downHead_[j] = first ? bin[j] : over(bin[j], downHead_[j - 1]);
    }
    for (int j = n - 1; j >= 0; --j) {
      const bool last = (j + 1) % count == 0 || j + 1 == n;  // the block's last sub-bin
      // Tails: j .. the block's end, increasing (up) and decreasing (down) order.
      upTail_[j] = last ? bin[j] : over(bin[j], upTail_[j + 1]);
      downTail_[j] = last ? bin[j] : over(downTail_[j + 1], bin[j]);
    }
  }
  // Sub-bins begin .. begin + count - 1, increasing.
  Span up(int begin) const {
    return begin % count_ == 0 ? upTail_[begin] : over(upTail_[begin], upHead_[begin + count_ - 1]);
  }
  // The same, decreasing.
  Span down(int begin) const {
    return begin % count_ == 0 ? downTail_[begin]
                               : over(downHead_[begin + count_ - 1], downTail_[begin]);
  }

 private:
  int count_ = 1;
  std::vector<Span> upHead_, upTail_, downHead_, downTail_;
};

}  // namespace

PreintegrationTable PreintegrationTable::build(const TransferFunction& tf, double lo, double hi,
                                               int size, double distance, int substeps) {
  return buildTable(tf, lo, hi, size, distance, substeps, Compositing::Blocks);
}

PreintegrationTable PreintegrationTable::buildBySegments(const TransferFunction& tf, double lo,
                                                         double hi, int size, double distance,
                                                         int substeps) {
  return buildTable(tf, lo, hi, size, distance, substeps, Compositing::EachSegment);
}

PreintegrationTable PreintegrationTable::buildTable(const TransferFunction& tf, double lo,
                                                    double hi, int size, double distance,
                                                    int substeps, Compositing compositing) {
  checkArguments(lo, hi, size, distance);
  if (substeps < 1) throw std::invalid_argument("pre-integration table: substeps must be >= 1");
  PreintegrationTable table;
  table.size_ = size;
  table.lo_ = lo;
  table.hi_ = hi;
  table.distance_ = distance;
  table.substeps_ = substeps;
  table.entries_.assign(size_t(size) * size_t(size), glm::vec4(0.0f));

  // Diagonal: constant scalar, closed form.
  const std::vector<glm::vec4> diagonal = buildPointTable(tf, lo, hi, size, distance);
  for (int i = 0; i < size; ++i) table.entries_[size_t(i) * size + i] = diagonal[i];

  // Sub-bins between table samples: mean extinction over the sub-bin (so a segment's opacity
  // is right even when a thin peak lies inside one) and the extinction-weighted mean colour.
  const int bins = (size - 1) * substeps;
  std::vector<double> tau(bins);
  std::vector<glm::dvec3> color(bins);
  for (int j = 0; j < bins; ++j) {
    double sum = 0.0;
    glm::dvec3 weighted(0.0);
    for (int q = 0; q < kSamplesPerSubBin; ++q) {
      const double s = scalarOf(lo, hi, size, (j + (q + 0.5) / kSamplesPerSubBin) / substeps);
      const double t = tf.extinctionAt(s);
      sum += t;
      weighted += t * tf.colorAt(s);
    }
    tau[j] = sum / kSamplesPerSubBin;
    color[j] = sum > 0.0 ? weighted / sum : glm::dvec3(0.0);
  }
  table.pointTau_.resize(size);
  for (int i = 0; i < size; ++i) table.pointTau_[i] = tf.extinctionAt(scalarOf(lo, hi, size, i));
  table.tauPrefix_.assign(size_t(bins) + 1, 0.0);
  for (int j = 0; j < bins; ++j) table.tauPrefix_[j + 1] = table.tauPrefix_[j] + tau[j];
  const bool each = compositing == Compositing::EachSegment;
  // Diagonals are independent; each core takes every lanes-th one.
  auto diagonals = [&](int first, int stride) {
    std::vector<Span> bin(bins);
    SpanBlocks blocks;
    for (int delta = first; delta < size; delta += stride) {
      // Every segment on this diagonal crosses delta * substeps sub-bins over the same length.
      const double step = distance / double(delta * substeps);
      for (int j = 0; j < bins; ++j) {
        const double alpha = -std::expm1(-tau[j] * step);
        bin[j] = Span{color[j] * alpha, 1.0 - alpha};
      }
      const int count = delta * substeps;
      if (!each) blocks.build(bin, count);
      for (int f = 0; f + delta < size; ++f) {
        // Increasing scalar (front f, back f + delta) and decreasing (front f + delta, back f):
        // the same sub-bins in opposite orders.
        const int begin = f * substeps;
        const Span up = each ? compositeUp(bin, begin, count) : blocks.up(begin);
        const Span down = each ? compositeDown(bin, begin, count) : blocks.down(begin);
        table.entries_[size_t(f) * size + (f + delta)] = entry(up);
        table.entries_[size_t(f + delta) * size + f] = entry(down);
      }
    }
  };
  // One lane of alternate diagonals a core: diagonal 1 + lane, then every lanes-th.
  const size_t lanes = std::min<size_t>(workerThreads(0), size_t(std::max(size - 1, 1)));
  parallelChunks(lanes, 1, unsigned(lanes), [&](size_t first, size_t last, size_t) {
    for (size_t lane = first; lane < last; ++lane) diagonals(int(lane) + 1, int(lanes));
  });
  return table;
}

double PreintegrationTable::meanExtinction(int front, int back) const {
  if (front == back) return pointTau_[size_t(front)];
  const int a = std::min(front, back) * substeps_, b = std::max(front, back) * substeps_;
  return (tauPrefix_[size_t(b)] - tauPrefix_[size_t(a)]) / double(b - a);
}

glm::dvec4 integrateSegment(const TransferFunction& tf, double sFront, double sBack,
                            double distance, int steps) {
  const double h = distance / steps;
  glm::dvec3 c(0.0);
  double t = 1.0;
  for (int i = 0; i < steps; ++i) {
    const double w = (i + 0.5) / steps;
    const double s = (1.0 - w) * sFront + w * sBack;
    const double alpha = -std::expm1(-tf.extinctionAt(s) * h);
    c += t * alpha * tf.colorAt(s);
    t *= 1.0 - alpha;
  }
  return glm::dvec4(c, 1.0 - t);
}

std::vector<glm::vec4> buildPointTable(const TransferFunction& tf, double lo, double hi, int size,
                                       double distance) {
  checkArguments(lo, hi, size, distance);
  std::vector<glm::vec4> table(size);
  for (int i = 0; i < size; ++i) {
    const double s = scalarOf(lo, hi, size, i);
    const double alpha = -std::expm1(-tf.extinctionAt(s) * distance);
    const glm::dvec3 c = tf.colorAt(s) * alpha;
    table[i] = glm::vec4(float(c.r), float(c.g), float(c.b), float(alpha));
  }
  return table;
}

}  // namespace ewa
