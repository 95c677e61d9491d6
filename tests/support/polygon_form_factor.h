// The form factor from a differential Lambertian receiver to any planar polygon, at any
// orientation, by Lambert's contour formula, written apart from the code it checks. With the
// cosine taken on one normal and the horizon on another (smooth normals), clip the polygon by
// both planes first. A receiver under an emitter of uniform radiance L gets E = π·L·F.
// (J. H. Lambert, Photometria, 1760; J. Arvo, "Applications of Irradiance Tensors to the
// Simulation of Non-Lambertian Phenomena", SIGGRAPH 1995, eq. 1.)
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>

namespace bounce::test {

// The part of `polygon` on the side n·(p − x) ≥ 0 of the plane through x with normal n
// (Sutherland–Hodgman against one plane; keeps the vertex order).
inline std::vector<glm::dvec3> clipPolygon(const std::vector<glm::dvec3>& polygon, glm::dvec3 x,
                                           glm::dvec3 n) {
  std::vector<glm::dvec3> out;
  const std::size_t m = polygon.size();
  for (std::size_t i = 0; i < m; ++i) {
    const glm::dvec3 a = polygon[i], b = polygon[(i + 1) % m];
    const double da = glm::dot(n, a - x), db = glm::dot(n, b - x);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// F = (1/2π) Σ_i θ_i · n·(v_{i+1} × v_i)/|v_{i+1} × v_i|, v_i = p_i − x, θ_i the angle between
// v_i and v_{i+1}: the flux through the receiver's unit normal n of the polygon's "vector
// irradiance". Vertices counter-clockwise as seen from x; exact when the polygon lies in
// front of the receiver (n·(p − x) ≥ 0 everywhere: clip it first otherwise).
inline double polygonFormFactor(const std::vector<glm::dvec3>& polygon, glm::dvec3 x,
                                glm::dvec3 n) {
  double sum = 0.0;
  const std::size_t m = polygon.size();
  for (std::size_t i = 0; i < m; ++i) {
    const glm::dvec3 a = polygon[i] - x, b = polygon[(i + 1) % m] - x;
    const glm::dvec3 c = glm::cross(b, a);
    const double length = glm::length(c);
    if (!(length > 0.0)) continue;  // a degenerate edge (e.g. from clipping) spans no angle
    const double theta = std::atan2(length, glm::dot(a, b));
    sum += theta * glm::dot(n, c) / length;
  }
  return sum / (2.0 * std::numbers::pi);
}

}  // namespace bounce::test
