// What a shadow map (or one cube face) was last drawn for: its light's view-projection and every
// instance's model matrix (the casters). While both stay, the depths it holds are the ones a
// redraw would give, so a still scene's maps are drawn once, whatever the camera does (only
// whether a map can reach the view depends on the camera: a map skipped as out of view is not
// stamped, and is drawn once it can be seen).
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/gpu_instance.h"

namespace bounce {

class ShadowMapStamp {
 public:
  bool matches(const glm::mat4& viewProjection, std::span<const GpuInstance> instances) const;
  void set(const glm::mat4& viewProjection, std::span<const GpuInstance> instances);
  // The map's texture was remade or its light changed: the next render draws it.
  void invalidate() { valid_ = false; }

 private:
  bool valid_ = false;
  glm::mat4 viewProjection_{0.0f};
  std::vector<glm::mat4> models_;
};

}  // namespace bounce
