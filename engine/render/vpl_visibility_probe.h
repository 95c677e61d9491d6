// Reads vplVisibility (shaders/vpl_shadows.glsl) back at chosen receivers: one fragment of
// shaders/vpl_visibility_probe.frag per receiver, into a float target. For tests and
// measurements of the VPL shadow maps against ray-traced visibility.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader.h"
#include "render/vpl_shadow_maps.h"

namespace bounce {

class VplVisibilityProbe {
 public:
  // Needs a current GL context; compiles the probe program from `shaderDir`.
  explicit VplVisibilityProbe(const std::filesystem::path& shaderDir);

  // vplVisibility(cube, positions[i], normals[i]) for every i (positions in metres, unit
  // geometric normals facing the VPL's side); the sizes must agree.
  std::vector<float> read(const VplShadowMaps& maps, int group,
                          std::span<const glm::vec3> positions, std::span<const glm::vec3> normals);

 private:
  gl::Program program_;
};

}  // namespace bounce
