// The scene's point, spot and directional lights as the uniform arrays of shaders/lights.glsl.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "scene/scene.h"

namespace bounce {

// Must match MAX_PUNCTUAL_LIGHTS in shaders/lights.glsl.
constexpr std::size_t kMaxPunctualLights = 32;

class PunctualLights {
 public:
  // The first kMaxPunctualLights of `scene.lights` (a warning says when there are more).
  PunctualLights(const Scene& scene, std::vector<std::string>& warnings);

  std::size_t size() const { return type_.size(); }
  // The scene light that uniform slot `i` holds (slot i = Scene::lights[i]).
  const Light& light(std::size_t i) const { return lights_[i]; }
  void set(gl::Program& program) const;
  // Lights marked Light::bakeDirect have their direct light in the lightmap once a bake is
  // attached: then they are drawn with zero power (they still occupy their slots). Without a
  // bake they are drawn live like the others.
  void setBakedDirectInLightmap(bool inLightmap) { bakedDirectInLightmap_ = inLightmap; }

 private:
  bool bakedDirectInLightmap_ = false;
  std::vector<Light> lights_;
  std::vector<int> type_;
  std::vector<glm::vec3> position_, direction_, power_;
  std::vector<glm::vec2> cosCone_;
};

}  // namespace bounce
