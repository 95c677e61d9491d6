// Directional-light shadows: cascaded orthographic depth maps fitted to the camera's frustum
// each frame (render/cascades.h), the cascades as the four tiles of one depth atlas read by
// shaders/shadow_directional.glsl. One directional light is shadowed at a time: the first in the
// scene until the shadow pass chooses the one that brings the most (punctual_shadow_budget.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/cascades.h"
#include "render/shadow_map_stamp.h"
#include "render/shadow_settings.h"

namespace bounce {

class GpuScene;

class DirectionalShadowMaps {
 public:
  DirectionalShadowMaps(const ShadowSettings& settings, const std::filesystem::path& shaderDir);

  // Gives `light` (directional) the cascades; returns 0, or −1 when another light has them.
  int add(const Light& light);
  // The light with the cascades turned or changed, or another light takes them (the next
  // render fits them again). The cascades must exist (add).
  void setLight(const Light& light) {
    light_ = light;
    drawn_.clear();
  }
  // No light has the cascades: they are not rendered (uCascadeCount 0).
  void release() {
    released_ = true;
    drawn_.clear();
  }
  void assign(const Light& light) {
    light_ = light;
    released_ = false;
    drawn_.clear();
  }
  // Fits the cascades to `camera` (image aspect `aspect`) and renders them, unless every cascade
  // and every instance is where it was when the atlas was last drawn (shadow_map_stamp.h): a
  // still camera over a still scene draws them once.
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
  bool released_ = false;
  std::optional<gl::Program> depth_;
  std::optional<gl::DepthTexture2D> atlas_;
  std::vector<Cascade> cascades_;
  std::vector<ShadowMapStamp> drawn_;  // per cascade, what the atlas holds
  Camera camera_;
  std::filesystem::path shaderDir_;
};

}  // namespace bounce
