// Opacity and colour correction: alpha' = 1 - (1 - alpha)^(d'/d), c' = c * alpha'/alpha.
#include "core/opacity_correction.h"

#include <algorithm>
#include <cmath>

namespace ewa {

double correctOpacity(double alpha, double ratio) {
  alpha = std::clamp(alpha, 0.0, 1.0);
  if (alpha >= 1.0) return 1.0;
  // -expm1(ratio * log1p(-alpha)) keeps precision for tiny alpha, where 1 - (1-a)^r cancels.
  return -std::expm1(ratio * std::log1p(-alpha));
}

glm::vec4 correctPremultiplied(const glm::vec4& rgba, double ratio) {
  const double alpha = rgba.a;
  const double corrected = correctOpacity(alpha, ratio);
  // Below 1e-7 the quotient is ratio to float precision; avoid 0/0.
  const double factor = alpha > 1e-7 ? corrected / alpha : ratio;
  return glm::vec4(float(rgba.r * factor), float(rgba.g * factor), float(rgba.b * factor),
                   float(corrected));
}

void correctTable(std::vector<glm::vec4>& table, double ratio) {
  if (ratio == 1.0) return;
  for (glm::vec4& e : table) e = correctPremultiplied(e, ratio);
}

}  // namespace ewa
