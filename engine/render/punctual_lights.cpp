#include "render/punctual_lights.h"

#include <cmath>

namespace bounce {
namespace {

// The LIGHT_* constants of shaders/light_table.glsl.
float shaderLightType(LightType type) {
  switch (type) {
    case LightType::Point:
      return 0.0f;
    case LightType::Spot:
      return 1.0f;
    case LightType::Directional:
      return 2.0f;
  }
  return 0.0f;
}

}  // namespace

PunctualLights::PunctualLights(const Scene& scene) : lights_(scene.lights), baked_(scene.lights) {}

int PunctualLights::bakedIndex(std::size_t i) const {
  if (i >= bakedCount_ || i >= baked_.size()) return -1;
  const Light& now = lights_[i];
  const Light& then = baked_[i];
  if (now.mobility != Mobility::Static || now.bakeDirect) return -1;
  // V depends on where the light is (point, spot) or the way it shines (directional, and a
  // spot's falloff over a texel); not on its power.
  if (now.position != then.position || now.direction != then.direction ||
      now.innerConeAngle != then.innerConeAngle || now.outerConeAngle != then.outerConeAngle)
    return -1;
  return bakedFirst_ + static_cast<int>(i);
}

bool PunctualLights::asBaked(std::size_t i) const {
  if (bakedIndex(i) < 0) return false;
  const Light& now = lights_[i];
  const Light& then = baked_[i];
  return now.intensity == then.intensity && now.irradiance == then.irradiance;
}

std::vector<uint32_t> PunctualLights::listOrder(std::span<const int> shadowSlots) const {
  std::vector<uint32_t> order;
  order.reserve(lights_.size());
  const auto first = [&](std::size_t i) {
    return precomputed(i) && !(i < shadowSlots.size() && shadowSlots[i] >= 0);
  };
  for (std::size_t i = 0; i < lights_.size(); ++i)
    if (first(i)) order.push_back(static_cast<uint32_t>(i));
  for (std::size_t i = 0; i < lights_.size(); ++i)
    if (!first(i)) order.push_back(static_cast<uint32_t>(i));
  return order;
}

glm::vec3 PunctualLights::drawnPower(std::size_t i) const {
  const Light& light = lights_[i];
  if (bakedDirectInLightmap_ && light.bakeDirect) return glm::vec3(0.0f);
  return light.type == LightType::Directional ? light.irradiance : light.intensity;
}

std::vector<glm::vec4> PunctualLights::texels(std::span<const int> shadowSlots) const {
  std::vector<glm::vec4> out;
  out.reserve(4 * lights_.size());
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = lights_[i];
    const glm::vec3 power = drawnPower(i);
    const int slot = i < shadowSlots.size() ? shadowSlots[i] : -1;
    out.emplace_back(light.position, shaderLightType(light.type));
    out.emplace_back(glm::normalize(light.direction), static_cast<float>(slot));
    out.emplace_back(power, static_cast<float>(bakedIndex(i)));
    // The same cosines bounce::spotFalloff computes, so the shader's falloff matches it.
    out.emplace_back(std::cos(light.innerConeAngle), std::cos(light.outerConeAngle),
                     precomputed(i) ? 1.0f : 0.0f, 0.0f);
  }
  return out;
}

}  // namespace bounce
