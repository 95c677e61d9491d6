#include "render/area_shadow_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "image/luminance.h"

namespace bounce {
namespace {

// Lambert's vector irradiance Φ of triangle (a, b, c) seen from the origin, per unit radiance,
// pointing from the origin towards the triangle: ½ Σ_edges θ_e·Γ_e, θ_e the angle the edge
// subtends and Γ_e the unit normal of the plane through the origin and the edge.
glm::dvec3 vectorIrradiance(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  if (la <= 0.0 || lb <= 0.0 || lc <= 0.0) return glm::dvec3(0.0);
  const glm::dvec3 u[3] = {a / la, b / lb, c / lc};
  glm::dvec3 phi(0.0);
  for (int e = 0; e < 3; ++e) {
    const glm::dvec3 cross = glm::cross(u[e], u[(e + 1) % 3]);
    const double s = glm::length(cross);
    if (s <= 1e-12) continue;
    const double theta = std::atan2(s, glm::dot(u[e], u[(e + 1) % 3]));
    phi += 0.5 * theta * (cross / s);
  }
  return glm::dot(phi, a + b + c) < 0.0 ? -phi : phi;
}

}  // namespace

float largestIrradiance(const AreaLightSet& set, std::size_t light, glm::vec3 p) {
  const AreaLight& l = set.lights[light];
  glm::dvec3 sum(0.0);
  float radiance = 0.0f;
  for (uint32_t t = l.first; t < l.first + l.count; ++t) {
    const EmitterTriangle& e = set.triangles[t];
    const glm::vec3 front = glm::cross(e.v1 - e.v0, e.v2 - e.v0);
    if (!e.doubleSided && glm::dot(front, p - e.v0) <= 0.0f) continue;  // behind it
    const double l_t = brightestChannel(e.radiance);
    radiance = std::max(radiance, brightestChannel(e.radiance));
    sum += l_t * vectorIrradiance(glm::dvec3(e.v0 - p), glm::dvec3(e.v1 - p), glm::dvec3(e.v2 - p));
  }
  // A hemisphere of radiance L gives π·L: no surface gets more.
  return std::min(static_cast<float>(glm::length(sum)), std::numbers::pi_v<float> * radiance);
}

std::vector<float> areaLightContributions(const AreaLightSet& set,
                                          const AreaShadowReceivers& receivers, float floor) {
  std::vector<float> contribution(set.lights.size(), 0.0f);
  for (std::size_t l = 0; l < set.lights.size(); ++l) {
    const AreaLight& light = set.lights[l];
    if (receivers.bakedDirectSkipped && light.bakeDirect) continue;
    float c = 0.0f;
    for (const AreaShadowReceivers::Dynamic& dynamic : receivers.dynamics) {
      if (dynamic.instance == light.instance || dynamic.box.empty()) continue;
      c = std::max(c, largestOverBox(dynamic.box, light.centre,
                                     [&](glm::vec3 p) { return largestIrradiance(set, l, p); }));
    }
    const ShadowReceivers::Stats view =
        l >= receivers.bakedVisibilityLights
            ? receivers.viewStats([&](glm::vec3 p) { return largestIrradiance(set, l, p); })
            : ShadowReceivers::Stats{};
    contribution[l] = shadowContribution(c, view, floor);
  }
  return contribution;
}

std::string describeAreaShadowChoice(const ShadowChoice& choice, int slots) {
  const auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return std::string(text);
  };
  std::string s = "area-light shadow cubes: ";
  s += std::to_string(choice.lights.size());
  s += " of ";
  s += std::to_string(slots);
  s += " slots in use";
  if (choice.unshadowed == 0) {
    s += "; every area light bringing light where the cubes are read has one";
    return s;
  }
  s += "; ";
  s += std::to_string(choice.unshadowed);
  s += " more lights bring light where the cubes are read but have none (dynamic instances and "
       "surfaces without baked visibility get no shadow from them): together ";
  s += number(choice.unshadowedContribution);
  s += " W/m², the strongest ";
  s += number(choice.largestUnshadowed);
  s += " W/m², ";
  s += number(choice.totalContribution > 0.0
                  ? 100.0 * choice.unshadowedContribution / choice.totalContribution
                  : 0.0);
  s += "% of every area light's contribution there";
  return s;
}

}  // namespace bounce
