#include "render/punctual_shadow_budget.h"

#include <algorithm>

#include "image/luminance.h"
#include "scene/light_falloff.h"

namespace bounce {

float largestPunctualIrradiance(const Light& light, glm::vec3 power, glm::vec3 p) {
  const float strength = brightestChannel(power);
  if (light.type == LightType::Directional) return strength;
  const glm::vec3 toPoint = p - light.position;
  // A surface at the light itself could get any irradiance: a millimetre bounds the 1/d².
  const float d2 = std::max(glm::dot(toPoint, toPoint), 1e-6f);
  float falloff = 1.0f;
  if (light.type == LightType::Spot)
    falloff = spotFalloff(light, glm::dot(light.direction, toPoint) / std::sqrt(d2));
  return strength * falloff / d2;
}

std::vector<float> punctualLightContributions(std::span<const Light> lights,
                                              std::span<const glm::vec3> power,
                                              const ShadowReceivers& receivers, float floor,
                                              std::span<const uint8_t> bakedOnStatics) {
  std::vector<float> contribution(lights.size(), 0.0f);
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const Light& light = lights[l];
    const glm::vec3 drawn = l < power.size() ? power[l] : glm::vec3(0.0f);
    if (brightestChannel(drawn) <= 0.0f) continue;
    float c = 0.0f;
    for (const ShadowReceivers::Dynamic& dynamic : receivers.dynamics) {
      if (dynamic.box.empty()) continue;
      c = std::max(c, largestOverBox(dynamic.box, light.position, [&](glm::vec3 p) {
                     return largestPunctualIrradiance(light, drawn, p);
                   }));
    }
    const bool baked = l < bakedOnStatics.size() && bakedOnStatics[l] != 0;
    const ShadowReceivers::Stats view =
        baked ? ShadowReceivers::Stats{} : receivers.viewStats([&](glm::vec3 p) {
          return largestPunctualIrradiance(light, drawn, p);
        });
    contribution[l] = shadowContribution(c, view, floor);
  }
  return contribution;
}

int PunctualShadowSlots::of(LightType type) const {
  if (type == LightType::Spot) return spot;
  if (type == LightType::Point) return point;
  return directional;
}

std::vector<int> assignPunctualShadowSlots(std::span<const Light> lights,
                                           std::span<const float> contributions,
                                           const PunctualShadowSlots& slots, float floor,
                                           std::span<const int> previous) {
  std::vector<int> assigned(lights.size(), -1);
  for (const LightType type : {LightType::Spot, LightType::Point, LightType::Directional}) {
    // This kind's lights compete among themselves: the others count as bringing nothing.
    std::vector<float> ofKind(lights.size(), 0.0f);
    std::vector<uint32_t> held;
    for (std::size_t l = 0; l < lights.size(); ++l) {
      if (lights[l].type != type) continue;
      ofKind[l] = l < contributions.size() ? contributions[l] : 0.0f;
      if (l < previous.size() && previous[l] >= 0) held.push_back(static_cast<uint32_t>(l));
    }
    const ShadowChoice choice = chooseShadowedLights(ofKind, slots.of(type), floor, held);
    std::vector<bool> taken(static_cast<std::size_t>(std::max(slots.of(type), 0)), false);
    const auto keeps = [&](uint32_t l) {
      const int slot = l < previous.size() ? previous[l] : -1;
      return slot >= 0 && slot < static_cast<int>(taken.size());
    };
    for (const uint32_t l : choice.lights)
      if (keeps(l)) {
        assigned[l] = previous[l];
        taken[static_cast<std::size_t>(previous[l])] = true;
      }
    for (const uint32_t l : choice.lights) {
      if (keeps(l)) continue;
      const auto free = std::find(taken.begin(), taken.end(), false);
      if (free == taken.end()) break;  // cannot happen: at most slots.of(type) are chosen
      *free = true;
      assigned[l] = static_cast<int>(free - taken.begin());
    }
    // A map changes hands only when another light is chosen for it: a light left unchosen
    // (bringing nothing where this frame's points fell, as in a close-up between them) keeps
    // the map no other light took.
    for (const uint32_t l : held)
      if (assigned[l] < 0 && keeps(l) && !taken[static_cast<std::size_t>(previous[l])]) {
        assigned[l] = previous[l];
        taken[static_cast<std::size_t>(previous[l])] = true;
      }
  }
  return assigned;
}

std::string describePunctualShadowMaps(std::span<const Light> lights, std::span<const int> slots) {
  std::string mapped, without;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    std::string& list = l < slots.size() && slots[l] >= 0 ? mapped : without;
    list += (list.empty() ? "'" : ", '") + lights[l].name + "'";
  }
  return "punctual shadow maps: " + (mapped.empty() ? std::string("none") : mapped) +
         (without.empty() ? std::string("; every punctual light has one")
                          : "; without one this frame: " + without);
}

}  // namespace bounce
