#include "render/shadow_receivers.h"

#include <algorithm>

namespace bounce {

ShadowReceivers shadowReceivers(const GpuScene& scene, const ViewVolume& view, bool viewPoints,
                                glm::vec3 eye) {
  ShadowReceivers where;
  const std::span<const GpuInstance> instances = scene.instances();
  for (std::size_t i = 0; i < instances.size(); ++i)
    if (instances[i].mobility == Mobility::Dynamic &&
        !intersect(instances[i].worldBox, view.box).empty())
      where.dynamics.push_back({instances[i].worldBox, static_cast<uint32_t>(i)});
  if (viewPoints)
    for (const GpuInstance& instance : instances) {
      if (instance.mobility != Mobility::Static ||
          scene.materials()[instance.material].emission != glm::vec3(0.0f))
        continue;
      const Box visible = intersect(instance.worldBox, view.box);
      if (visible.empty() || !view.frustum.overlaps(visible)) continue;
      const glm::vec3 cell = (visible.upper - visible.lower) / 3.0f;
      const float area = std::max({cell.x * cell.y, cell.y * cell.z, cell.z * cell.x});
      for (const glm::vec3& p : viewSamplePoints(view.frustum, visible, 3)) {
        where.viewPoints.push_back(p);
        where.viewWeights.push_back(viewPointWeight(eye, p, area));
      }
    }
  // Every frame costs lights × points irradiance evaluations: a scene of many instances keeps
  // an even spread of at most kMaxViewPoints.
  constexpr std::size_t kMaxViewPoints = 512;
  if (where.viewPoints.size() > kMaxViewPoints) {
    std::vector<glm::vec3> spread;
    std::vector<float> weights;
    for (std::size_t k = 0; k < kMaxViewPoints; ++k) {
      const std::size_t i = k * where.viewPoints.size() / kMaxViewPoints;
      spread.push_back(where.viewPoints[i]);
      weights.push_back(where.viewWeights[i]);
    }
    where.viewPoints = std::move(spread);
    where.viewWeights = std::move(weights);
  }
  return where;
}

}  // namespace bounce
