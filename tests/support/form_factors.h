// Closed-form form factors from a differential Lambertian receiver to a rectangle, the
// analytic values the renderer and the path tracer are tested against. A receiver under an
// emitter of uniform radiance L gets irradiance E = π·L·F and reflects Lo = ρ·L·F.
// (Howell, "A Catalog of Radiation Heat Transfer Configuration Factors": differential element
// to a parallel rectangle with its normal through a corner, and to a perpendicular rectangle.)
#pragma once

#include <cmath>
#include <numbers>

namespace bounce::test {

// Parallel rectangle [0,a]×[0,b] at distance c, the receiver's normal through the corner (0,0):
//   F = 1/(2π) [A/√(1+A²) atan(B/√(1+A²)) + B/√(1+B²) atan(A/√(1+B²))],  A = a/c, B = b/c.
// Odd in a and in b, so any rectangle follows by inclusion–exclusion of signed corners.
inline double parallelCornerFormFactor(double a, double b, double c) {
  const double A = a / c, B = b / c;
  const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * std::numbers::pi);
}

// Parallel rectangle [x0,x1]×[y0,y1] at distance c, seen from the receiver at (x, y).
inline double parallelRectangleFormFactor(double x, double y, double x0, double x1, double y0,
                                          double y1, double c) {
  return parallelCornerFormFactor(x1 - x, y1 - y, c) - parallelCornerFormFactor(x0 - x, y1 - y, c) -
         parallelCornerFormFactor(x1 - x, y0 - y, c) + parallelCornerFormFactor(x0 - x, y0 - y, c);
}

// Rectangle in a perpendicular plane at distance d, spanning W sideways from the receiver's
// foot and H up from the receiver's own plane:
//   F = 1/(2π) [atan(W/d) − d/√(d²+H²) · atan(W/√(d²+H²))].
inline double perpendicularFormFactor(double d, double H, double W) {
  const double s = std::sqrt(d * d + H * H);
  return (std::atan(W / d) - d / s * std::atan(W / s)) / (2 * std::numbers::pi);
}

}  // namespace bounce::test
