#include "render/light_reach.h"

#include <algorithm>
#include <cmath>

#include "image/luminance.h"
#include "render/light_cutoff.h"

namespace bounce {

LightReach punctualReach(const Light& light, glm::vec3 power, float floor) {
  LightReach reach;
  if (!(brightestChannel(power) > 0.0f)) return reach;  // Shape::None: the shader skips it too
  if (light.type == LightType::Directional) {
    reach.shape = LightReach::Shape::Everywhere;
    return reach;
  }
  reach.shape = light.type == LightType::Spot ? LightReach::Shape::Cone : LightReach::Shape::Sphere;
  reach.centre = light.position;
  reach.radius = cutoffDistance(brightestChannel(power), floor);
  reach.axis = glm::normalize(light.direction);
  reach.cosOuter = std::cos(light.outerConeAngle);
  reach.sinOuter = std::sin(light.outerConeAngle);
  return reach;
}

std::vector<LightReach> areaReaches(const AreaLightSet& set, float floor) {
  std::vector<LightReach> out;
  out.reserve(set.lights.size());
  for (const AreaLight& light : set.lights) {
    LightReach reach;
    reach.shape = LightReach::Shape::Box;
    float intensity = 0.0f;  // Σ L·A, W/sr: the inverse-square bound's numerator
    for (uint32_t t = light.first; t < light.first + light.count; ++t) {
      const EmitterTriangle& e = set.triangles[t];
      for (const glm::vec3& v : {e.v0, e.v1, e.v2}) reach.box.grow(v);
      intensity +=
          brightestChannel(e.radiance) * 0.5f * glm::length(glm::cross(e.v1 - e.v0, e.v2 - e.v0));
    }
    reach.radius = cutoffDistance(intensity, floor);
    if (!(intensity > 0.0f) || reach.box.empty()) reach.shape = LightReach::Shape::None;
    out.push_back(reach);
  }
  return out;
}

}  // namespace bounce
