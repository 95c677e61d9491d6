// Point-light shadows: one cube map per point light (six 90° faces), storing the distance to
// the light (shaders/shadow_point.glsl reads them).
#pragma once

#include <array>
#include <vector>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/shadow_casters.h"
#include "render/shadow_map_geometry.h"
#include "render/shadow_map_stamp.h"

namespace bounce {

class GpuScene;

class PointShadowMaps {
 public:
  explicit PointShadowMaps(const ShadowSettings& settings) : settings_(settings) {}

  // Gives `light` (a point light) a cube; returns its slot, or −1 when all kMaxPointShadows are
  // taken.
  int add(const Light& light, const Box& sceneBox);
  // Cube `slot` (at most one past the last) shadows `light` from now on: the budget gave it
  // another light (punctual_shadow_budget.h). Its texture is remade if its resolution changes.
  void assign(int slot, const Light& light, const Box& sceneBox);
  // Cube `slot` shadows no light: it is not rendered.
  void release(int slot) { cubes_.at(static_cast<std::size_t>(slot)).used = false; }
  // The light of cube `slot` moved or changed (its faces follow on the next render).
  void setLight(int slot, const Light& light) {
    cubes_.at(static_cast<std::size_t>(slot)).light = light;
    for (ShadowMapStamp& face : cubes_.at(static_cast<std::size_t>(slot)).drawn) face.invalidate();
  }
  // Renders the faces that may reach `view` (ViewVolume::mayReach) and whose light or casters
  // changed since they were last drawn (shadow_map_stamp.h).
  ShadowDrawCount render(const GpuScene& scene, const ViewVolume& view, gl::Program& depthProgram,
                         gl::DepthTarget& target);
  void bind(gl::Program& forward) const;

 private:
  struct Cube {
    Light light;
    gl::DepthCubeMap texture;
    int resolution = 0;
    float far = 1.0f;
    bool used = true;
    std::array<ShadowMapStamp, 6> drawn;  // what each face holds (shadow_map_stamp.h)
  };
  ShadowSettings settings_;
  std::vector<Cube> cubes_;
};

}  // namespace bounce
