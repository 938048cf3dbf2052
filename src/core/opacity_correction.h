// Opacity and colour correction for a sample distance d' that differs from the table's d.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

namespace ewa {

// alpha' = 1 - (1 - alpha)^(d'/d): the opacity of a layer d' thick when alpha is that of one d
// thick (Schulze et al. 2003, Sec. 2.2). `ratio` is d'/d > 0.
double correctOpacity(double alpha, double ratio);

// Premultiplied colour and opacity (r, g, b, alpha) corrected together: alpha' as above and
// c' = c * alpha' / alpha, which keeps the colour per unit opacity. For alpha -> 0 the factor
// alpha'/alpha tends to `ratio` (emission proportional to length), which is used there.
glm::vec4 correctPremultiplied(const glm::vec4& rgba, double ratio);

// Corrects every entry of a premultiplied RGBA table in place (ratio 1 leaves it unchanged).
void correctTable(std::vector<glm::vec4>& table, double ratio);

}  // namespace ewa
