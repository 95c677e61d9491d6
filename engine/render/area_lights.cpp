#include "render/area_lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bounce {

std::vector<AreaLight> groupAreaLights(const std::vector<EmitterTriangle>& emitters) {
  std::vector<AreaLight> lights;
  for (uint32_t t = 0; t < emitters.size(); ++t) {
    const EmitterTriangle& e = emitters[t];
    auto light = std::find_if(lights.begin(), lights.end(), [&](const AreaLight& l) {
      return l.instance == e.instance && l.material == e.material;
    });
    if (light == lights.end()) {
      lights.emplace_back();
      light = std::prev(lights.end());
      light->instance = e.instance;
      light->material = e.material;
      light->doubleSided = e.doubleSided;
    }
    light->triangles.push_back(t);
  }
  for (AreaLight& light : lights) {
    glm::dvec3 weighted(0.0), normal(0.0), flux(0.0);
    double area = 0.0;
    for (const uint32_t t : light.triangles) {
      const EmitterTriangle& e = emitters[t];
      const glm::dvec3 cross = glm::cross(glm::dvec3(e.v1 - e.v0), glm::dvec3(e.v2 - e.v0));
      const double a = 0.5 * glm::length(cross);
      weighted += a * glm::dvec3(e.v0 + e.v1 + e.v2) / 3.0;
      normal += 0.5 * cross;
      area += a;
      // A Lambertian emitter of radiance L and area A emits π·L·A per face.
      flux += std::numbers::pi * a * glm::dvec3(e.radiance) * (e.doubleSided ? 2.0 : 1.0);
    }
    light.area = static_cast<float>(area);
    light.centre = area > 0.0 ? glm::vec3(weighted / area) : emitters[light.triangles[0]].v0;
    const double length = glm::length(normal);
    light.normal = length > 1e-6 * area ? glm::vec3(normal / length) : glm::vec3(0.0f);
    light.flux = glm::vec3(flux);
    for (const uint32_t t : light.triangles)
      for (const glm::vec3& v : {emitters[t].v0, emitters[t].v1, emitters[t].v2})
        light.radius = std::max(light.radius, glm::length(v - light.centre));
  }
  return lights;
}

std::vector<uint32_t> pickShadowedAreaLights(const std::vector<AreaLight>& lights,
                                             int maxShadowed) {
  std::vector<uint32_t> order(lights.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto total = [&](uint32_t i) {
    return lights[i].flux.r + lights[i].flux.g + lights[i].flux.b;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return total(a) > total(b); });
  order.resize(std::min(order.size(), static_cast<std::size_t>(std::max(maxShadowed, 0))));
  return order;
}

namespace {

// The radical inverse in base 2 (van der Corput): the second Hammersley coordinate.
double radicalInverse2(uint32_t i) {
  uint32_t bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return static_cast<double>(bits) * 0x1p-32;
}

}  // namespace

std::vector<glm::vec3> samplePoints(const AreaLight& light,
                                    const std::vector<EmitterTriangle>& emitters, int count) {
  std::vector<double> cdf;
  double total = 0.0;
  for (const uint32_t t : light.triangles) {
    const EmitterTriangle& e = emitters[t];
    total += 0.5 * glm::length(glm::cross(glm::dvec3(e.v1 - e.v0), glm::dvec3(e.v2 - e.v0)));
    cdf.push_back(total);
  }
  std::vector<glm::vec3> points;
  for (int k = 0; k < count; ++k) {
    // First coordinate picks the triangle by area and is reused within it, second is base 2.
    double u = (k + 0.5) / count * total;
    const std::size_t i = static_cast<std::size_t>(
        std::min<std::ptrdiff_t>(std::lower_bound(cdf.begin(), cdf.end(), u) - cdf.begin(),
                                 static_cast<std::ptrdiff_t>(cdf.size()) - 1));
    const double lo = i == 0 ? 0.0 : cdf[i - 1];
    u = std::clamp((u - lo) / std::max(cdf[i] - lo, 1e-30), 0.0, 1.0);
    const double v = radicalInverse2(static_cast<uint32_t>(k));
    // Uniform over the triangle: barycentrics (1 − √u, √u(1 − v), √u·v).
    const double su = std::sqrt(u);
    const EmitterTriangle& e = emitters[light.triangles[i]];
    points.push_back(glm::vec3((1.0 - su) * glm::dvec3(e.v0) + su * (1.0 - v) * glm::dvec3(e.v1) +
                               su * v * glm::dvec3(e.v2)));
  }
  return points;
}

}  // namespace bounce
