// The shadow pass: before the lit pass, renders a depth map for each shadowed light whose
// light can reach what the camera sees (spot: spot_shadow_maps.h; point: point_shadow_maps.h),
// then hands the maps to the lit pass. Which light has which map is uLightShadow[i] in
// shaders/shadows.glsl: the slot among its kind's maps, or −1 (unshadowed).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/gpu_scene.h"
#include "render/point_shadow_maps.h"
#include "render/punctual_lights.h"
#include "render/spot_shadow_maps.h"

namespace bounce {

class ShadowPass {
 public:
  ShadowPass(const GpuScene& scene, const PunctualLights& lights, const ShadowSettings& settings,
             const std::filesystem::path& shaderDir, std::vector<std::string>& warnings);

  // `visibleBox`: world box of what the camera can see (its frustum within the scene bounds).
  void render(const GpuScene& scene, const Box& visibleBox);
  // Binds the maps and sets every shadow uniform of the forward program.
  void bind(gl::Program& forward) const;

 private:
  ShadowSettings settings_;
  gl::Program depth_;
  gl::DepthTarget target_;
  std::vector<int> lightSlot_;  // per punctual light: its map's slot in its kind, −1 for none
  SpotShadowMaps spot_;
  PointShadowMaps point_;
};

}  // namespace bounce
