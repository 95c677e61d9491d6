#include "render/punctual_lights.h"

#include <cmath>
#include <span>

namespace bounce {
namespace {

// The LIGHT_* constants of shaders/lights.glsl.
int shaderLightType(LightType type) {
  switch (type) {
    case LightType::Point:
      return 0;
    case LightType::Spot:
      return 1;
    case LightType::Directional:
      return 2;
  }
  return 0;
}

}  // namespace

PunctualLights::PunctualLights(const Scene& scene, std::vector<std::string>& warnings) {
  for (const Light& light : scene.lights) {
    if (type_.size() == kMaxPunctualLights) {
      warnings.push_back(std::to_string(scene.lights.size()) + " punctual lights; only the first " +
                         std::to_string(kMaxPunctualLights) + " are drawn");
      break;
    }
    lights_.push_back(light);
    type_.push_back(shaderLightType(light.type));
    position_.push_back(light.position);
    direction_.push_back(glm::normalize(light.direction));
    power_.push_back(light.type == LightType::Directional ? light.irradiance : light.intensity);
    // The same cosines bounce::spotFalloff computes, so the shader's falloff matches it.
    cosCone_.emplace_back(std::cos(light.innerConeAngle), std::cos(light.outerConeAngle));
  }
}

void PunctualLights::set(gl::Program& program) const {
  program.set("uLightCount", static_cast<int>(type_.size()));
  program.set("uLightType", std::span<const int>(type_));
  program.set("uLightPosition", std::span<const glm::vec3>(position_));
  program.set("uLightDirection", std::span<const glm::vec3>(direction_));
  if (bakedDirectInLightmap_) {
    std::vector<glm::vec3> live = power_;
    for (std::size_t i = 0; i < live.size(); ++i)
      if (lights_[i].bakeDirect) live[i] = glm::vec3(0.0f);
    program.set("uLightPower", std::span<const glm::vec3>(live));
  } else {
    program.set("uLightPower", std::span<const glm::vec3>(power_));
  }
  program.set("uLightCosCone", std::span<const glm::vec2>(cosCone_));
}

}  // namespace bounce
