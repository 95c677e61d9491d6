// Closed forms for delta lights on a Lambertian surface whose shading normal differs from its
// geometric normal (smooth normals), written apart from the path tracer they check. The
// surface reflects light arriving from the front of its geometric surface (n_g·ω > 0) with
// the cosine taken on the shading normal, clamped at zero: Lo = ρ/π · E⊥ · max(0, n_s·ω),
// E⊥ the irradiance at normal incidence (W/m²), ω the unit direction towards the light.
#pragma once

#include <algorithm>
#include <numbers>

#include <glm/glm.hpp>

namespace bounce::test {

// Lo (W/(sr·m²)) at `x` for light of normal-incidence irradiance `e` arriving from `towards`.
inline glm::dvec3 lambertianRadiance(glm::dvec3 albedo, glm::dvec3 e, glm::dvec3 towards,
                                     glm::dvec3 shadingNormal, glm::dvec3 geometricNormal) {
  const glm::dvec3 w = glm::normalize(towards);
  if (glm::dot(glm::normalize(geometricNormal), w) <= 0.0) return glm::dvec3(0.0);
  const double cosShading = std::max(0.0, glm::dot(glm::normalize(shadingNormal), w));
  return albedo / std::numbers::pi * e * cosShading;
}

// A point light of intensity I (W/sr) at `light`: E⊥ = I/r² (inverse-square law).
inline glm::dvec3 pointLightRadiance(glm::dvec3 albedo, glm::dvec3 intensity, glm::dvec3 light,
                                     glm::dvec3 x, glm::dvec3 shadingNormal,
                                     glm::dvec3 geometricNormal) {
  const glm::dvec3 d = light - x;
  return lambertianRadiance(albedo, intensity / glm::dot(d, d), d, shadingNormal, geometricNormal);
}

}  // namespace bounce::test
