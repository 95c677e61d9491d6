// The exact area of a convex polygon inside an axis-aligned box (Sutherland–Hodgman against the
// box's four sides, then the shoelace formula): the independent reference for texel coverage
// (tests/atlas) and pixel coverage under multisampling (tests/render).
#pragma once

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

namespace bounce::test {

inline double clippedArea(std::vector<glm::dvec2> poly, glm::dvec2 lo, glm::dvec2 hi) {
  auto clip = [&](int axis, double bound, bool keepBelow) {
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      const bool ina = keepBelow ? a[axis] <= bound : a[axis] >= bound;
      const bool inb = keepBelow ? b[axis] <= bound : b[axis] >= bound;
      if (ina) out.push_back(a);
      if (ina != inb) out.push_back(a + (b - a) * ((bound - a[axis]) / (b[axis] - a[axis])));
    }
    poly = out;
  };
  clip(0, lo.x, false);
  if (!poly.empty()) clip(0, hi.x, true);
  if (!poly.empty()) clip(1, lo.y, false);
  if (!poly.empty()) clip(1, hi.y, true);
  double area = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::abs(area);
}

}  // namespace bounce::test
