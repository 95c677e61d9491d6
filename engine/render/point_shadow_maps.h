// Point-light shadows: one cube map per point light (six 90° faces), storing the distance to
// the light (shaders/shadow_point.glsl reads them).
#pragma once

#include <array>
#include <vector>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/gpu_scene.h"
#include "render/shadow_map_geometry.h"

namespace bounce {

class PointShadowMaps {
 public:
  explicit PointShadowMaps(const ShadowSettings& settings) : settings_(settings) {}

  // Gives `light` (a point light) a cube; returns its slot, or −1 when all kMaxPointShadows are
  // taken.
  int add(const Light& light, const Box& sceneBox);
  // Renders the faces whose frustum reaches `visibleBox`.
  void render(const GpuScene& scene, const Box& visibleBox, gl::Program& depthProgram,
              gl::DepthTarget& target);
  void bind(gl::Program& forward) const;

 private:
  struct Cube {
    Light light;
    gl::DepthCubeMap texture;
    int resolution = 0;
    float far = 1.0f;
  };
  ShadowSettings settings_;
  std::vector<Cube> cubes_;
};

}  // namespace bounce
