// Spot-light shadows: one perspective map per spot light along its axis, covering its outer
// cone, storing the distance to the light (shaders/shadow_spot.glsl reads them).
#pragma once

#include <vector>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/shadow_casters.h"
#include "render/shadow_map_geometry.h"
#include "render/shadow_map_stamp.h"

namespace bounce {

class GpuScene;

class SpotShadowMaps {
 public:
  explicit SpotShadowMaps(const ShadowSettings& settings) : settings_(settings) {}

  // Gives `light` (a spot) a map; returns its slot, or −1 when all kMaxSpotShadows are taken.
  int add(const Light& light, const Box& sceneBox);
  // Map `slot` (at most one past the last) shadows `light` from now on: the budget gave it
  // another light (punctual_shadow_budget.h). Its texture is remade if its resolution changes.
  void assign(int slot, const Light& light, const Box& sceneBox);
  // Map `slot` shadows no light: it is not rendered.
  void release(int slot) { maps_.at(static_cast<std::size_t>(slot)).used = false; }
  // The light of map `slot` moved or changed (its view follows on the next render).
  void setLight(int slot, const Light& light) {
    maps_.at(static_cast<std::size_t>(slot)).light = light;
    maps_.at(static_cast<std::size_t>(slot)).drawn.invalidate();
  }
  // Renders the maps that may reach `view` (ViewVolume::mayReach) and whose light or casters
  // changed since they were last drawn (shadow_map_stamp.h).
  ShadowDrawCount render(const GpuScene& scene, const ViewVolume& view, gl::Program& depthProgram,
                         gl::DepthTarget& target);
  // Binds the maps and sets uSpotShadow* on the forward program.
  void bind(gl::Program& forward) const;

 private:
  struct Map {
    Light light;
    gl::DepthTexture2D texture;
    ShadowView view;
    bool used = true;
    ShadowMapStamp drawn;  // what the texture holds (a still scene's map is drawn once)
  };
  ShadowSettings settings_;
  std::vector<Map> maps_;
};

}  // namespace bounce
