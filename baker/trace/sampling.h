// Warps of uniform [0,1)² samples onto the domains the path tracer integrates over, with
// their densities. Solid-angle densities are per steradian, area densities per m².
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "image/luminance.h"

namespace bounce {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;

// An orthonormal basis (t, b, n) around a unit normal n (Duff et al. 2017, branch-free).
struct Frame {
  glm::vec3 t, b, n;
  explicit Frame(glm::vec3 normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
  }
  glm::vec3 toWorld(glm::vec3 local) const { return local.x * t + local.y * b + local.z * n; }
};

// Concentric map of the square onto the unit disk (Shirley–Chiu): area-preserving, so
// stratification of u carries over to the disk.
inline glm::vec2 sampleConcentricDisk(glm::vec2 u) {
  const glm::vec2 o = 2.0f * u - 1.0f;
  if (o.x == 0.0f && o.y == 0.0f) return {0.0f, 0.0f};
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = 0.25f * kPi * (o.y / o.x);
  } else {
    r = o.y;
    theta = 0.5f * kPi - 0.25f * kPi * (o.x / o.y);
  }
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

// Cosine-weighted direction about +z (Malley): pdf(ω) = cosθ/π.
inline glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
  const glm::vec2 d = sampleConcentricDisk(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

inline float cosineHemispherePdf(float cosTheta) {
  return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f;
}

// Barycentrics (b1, b2) of a uniformly distributed point on a triangle: pdf = 1/area.
inline glm::vec2 sampleUniformTriangle(glm::vec2 u) {
  const float s = std::sqrt(u.x);
  return {1.0f - s, u.y * s};
}

// Veach's power heuristic (β = 2) weight for strategy a against strategy b.
inline float powerHeuristic(float pdfA, float pdfB) {
  const float a2 = pdfA * pdfA;
  const float b2 = pdfB * pdfB;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

inline float maxComponent(glm::vec3 v) {
  return std::max(v.x, std::max(v.y, v.z));
}
inline bool isFinite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace bounce
