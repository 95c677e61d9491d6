#include "render/shadow_map_stamp.h"

namespace bounce {

bool ShadowMapStamp::matches(const glm::mat4& viewProjection,
                             std::span<const GpuInstance> instances) const {
  if (!valid_ || viewProjection != viewProjection_ || instances.size() != models_.size())
    return false;
  for (std::size_t i = 0; i < instances.size(); ++i)
    if (instances[i].model != models_[i]) return false;
  return true;
}

void ShadowMapStamp::set(const glm::mat4& viewProjection, std::span<const GpuInstance> instances) {
  valid_ = true;
  viewProjection_ = viewProjection;
  models_.clear();
  for (const GpuInstance& instance : instances) models_.push_back(instance.model);
}

}  // namespace bounce
