#include "render/shadow_choice.h"

#include <algorithm>

namespace bounce {

std::vector<glm::vec3> viewSamplePoints(const Frustum& frustum, const Box& box, int perAxis) {
  std::vector<glm::vec3> points;
  if (box.empty() || perAxis <= 0) return points;
  const glm::vec3 cell = (box.upper - box.lower) / static_cast<float>(perAxis);
  for (int i = 0; i < perAxis; ++i)
    for (int j = 0; j < perAxis; ++j)
      for (int k = 0; k < perAxis; ++k) {
        const glm::vec3 p = box.lower + cell * (glm::vec3(i, j, k) + 0.5f);
        if (frustum.overlaps(Box{p, p})) points.push_back(p);
      }
  return points;
}

float viewPointWeight(glm::vec3 eye, glm::vec3 p, float area) {
  const float d2 = glm::dot(p - eye, p - eye);
  return d2 > area ? area / d2 : 1.0f;
}

float shadowContribution(float atDynamics, ShadowReceivers::Stats view, float floor) {
  if (std::max(static_cast<double>(atDynamics), view.largest) < static_cast<double>(floor))
    return 0.0f;
  return std::max(atDynamics, static_cast<float>(view.mean));
}

ShadowChoice chooseShadowedLights(std::span<const float> contributions, int slots, float floor,
                                  std::span<const uint32_t> previous) {
  ShadowChoice choice;
  std::vector<uint32_t> order;
  for (uint32_t l = 0; l < contributions.size(); ++l) {
    choice.totalContribution += contributions[l];
    if (contributions[l] >= floor && contributions[l] > 0.0f) order.push_back(l);
  }
  // A light holding a slot ranks 10% higher: a rival must bring clearly more to take it.
  const auto rank = [&](uint32_t l) {
    const bool held = std::find(previous.begin(), previous.end(), l) != previous.end();
    return contributions[l] * (held ? 1.1f : 1.0f);
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return rank(a) > rank(b); });
  const std::size_t kept = std::min(order.size(), static_cast<std::size_t>(std::max(slots, 0)));
  choice.lights.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(kept));
  for (std::size_t i = kept; i < order.size(); ++i) {
    ++choice.unshadowed;
    choice.unshadowedContribution += contributions[order[i]];
    choice.largestUnshadowed = std::max(choice.largestUnshadowed, contributions[order[i]]);
  }
  // Largest contribution first (the 10% rule only decides membership).
  std::stable_sort(choice.lights.begin(), choice.lights.end(),
                   [&](uint32_t a, uint32_t b) { return contributions[a] > contributions[b]; });
  return choice;
}

}  // namespace bounce
