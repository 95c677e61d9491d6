// Directional-light shadows: cascaded orthographic depth maps fitted to the camera's frustum
// each frame (render/cascades.h), the cascades as the four tiles of one depth atlas read by
// shaders/shadow_directional.glsl. One directional light is shadowed: the first in the scene
// (a warning says when more exist).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/cascades.h"
#include "render/gpu_scene.h"
#include "render/shadow_settings.h"

namespace bounce {

class DirectionalShadowMaps {
 public:
  DirectionalShadowMaps(const ShadowSettings& settings, const std::filesystem::path& shaderDir);

  // Gives `light` (directional) the cascades; returns 0, or −1 when another light has them.
  int add(const Light& light);
  // The light with the cascades turned or changed (the next render fits them again).
  void setLight(const Light& light) { light_ = light; }
  // Fits the cascades to `camera` (image aspect `aspect`) and renders them.
  ShadowDrawCount render(const GpuScene& scene, const Camera& camera, float aspect,
                         gl::DepthTarget& target);
  // Binds the atlas and sets uCascade*, uView* on the forward program (uCascadeCount 0 when no
  // light has cascades).
  void bind(gl::Program& forward) const;

  const std::vector<Cascade>& cascades() const { return cascades_; }

 private:
  ShadowSettings settings_;
  CascadeSettings cascadeSettings_;
  std::optional<Light> light_;
  std::optional<gl::Program> depth_;
  std::optional<gl::DepthTexture2D> atlas_;
  std::vector<Cascade> cascades_;
  Camera camera_;
  std::filesystem::path shaderDir_;
};

}  // namespace bounce
