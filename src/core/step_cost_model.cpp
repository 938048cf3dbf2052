// StepCostModel: prices of entries, slab clears, pass pixels and opacity checks from measured
// chunks.
#include "core/step_cost_model.h"

#include <algorithm>
#include <cmath>

namespace ewa {

namespace {

double blend(double old, double now) {
  return old > 0.0 && now < old ? 0.5 * (old + now) : now;
}

}  // namespace

void StepCostModel::update(const Chunk& c) {
  if (!std::isfinite(c.ms) || c.ms < 0.0) return;
  const double pixels = double(std::max(c.pixels, 0LL));
  if (c.entries == 0 && pixels == 0.0 && c.checks == 0 && c.begins == 0) return;
  if (msPerEntry_ <= 0.0 || (pixels == 0.0 && c.checks == 0 && c.begins == 0)) {
    // Without a known price an entry, the whole time is charged to the entries (safe: high).
    msPerEntry_ = blend(msPerEntry_, c.ms / double(std::max<size_t>(c.entries, 1)));
    return;
  }
  const double rest = std::max(0.0, c.ms - msPerEntry_ * double(c.entries));
  struct Part {
    double& price;
    double count;
  };
  Part parts[] = {
      {msPerPixel_, pixels}, {msPerBegin_, double(c.begins)}, {msPerCheck_, double(c.checks)}};
  double known = 0.0;
  for (const Part& p : parts)
    if (p.count > 0.0 && p.price > 0.0) known += p.price * p.count;
  for (Part& p : parts) {
    if (p.count > 0.0 && p.price <= 0.0) {
      p.price = std::max(0.0, rest - known) / p.count;
      return;
    }
  }
  if (known <= 0.0) return;
  const double scale = rest / known;
  for (Part& p : parts)
    if (p.count > 0.0) p.price = blend(p.price, p.price * scale);
}

int passRowsToDraw(int rowsLeft, double rowMs, double roomMs, bool firstWork, int bandRows,
                   int minRows) {
  rowsLeft = std::max(rowsLeft, 0);
  if (rowMs * double(rowsLeft) <= roomMs) return rowsLeft;
  const double fit = rowMs > 0.0 ? roomMs / rowMs : double(rowsLeft);
  int rows = int(std::clamp(fit, 0.0, double(rowsLeft))) / bandRows * bandRows;
  if (rows < minRows) {
    if (!firstWork) return 0;
    rows = minRows;
  }
  return rowsLeft - rows < minRows ? rowsLeft : rows;
}

}  // namespace ewa
