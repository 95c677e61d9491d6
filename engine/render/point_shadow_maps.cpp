#include "render/point_shadow_maps.h"

#include "render/shadow_casters.h"
#include "render/texture_units.h"

namespace bounce {

int PointShadowMaps::add(const Light& light, const Box& sceneBox) {
  if (static_cast<int>(cubes_.size()) == kMaxPointShadows) return -1;
  int resolution = settings_.resolution;
  if (resolution <= 0)
    resolution = defaultShadowResolution(light.position, sceneBox, 2.0f, 256, 1024);
  cubes_.push_back({light, gl::DepthCubeMap(resolution), resolution, 1.0f});
  return static_cast<int>(cubes_.size()) - 1;
}

void PointShadowMaps::render(const GpuScene& scene, const Box& visibleBox,
                             gl::Program& depthProgram, gl::DepthTarget& target) {
  const Box sceneBox = scene.bounds();
  for (Cube& cube : cubes_) {
    for (int face = 0; face < 6; ++face) {
      const ShadowView view =
          cubeFaceShadowView(cube.light.position, face, sceneBox, cube.resolution);
      cube.far = view.far;
      if (!Frustum(view.viewProjection).overlaps(visibleBox)) continue;
      target.bind(cube.texture, face);
      drawShadowCasters(scene, view, cube.light.position, depthProgram);
    }
  }
}

void PointShadowMaps::bind(gl::Program& forward) const {
  std::vector<int> units;
  std::vector<glm::vec4> params;
  for (int slot = 0; slot < kMaxPointShadows; ++slot)
    units.push_back(TextureUnit::kPointShadow0 + slot);
  for (std::size_t slot = 0; slot < cubes_.size(); ++slot) {
    const Cube& cube = cubes_[slot];
    cube.texture.bind(TextureUnit::kPointShadow0 + static_cast<int>(slot));
    params.emplace_back(2.0f / static_cast<float>(cube.resolution), cube.far,
                        settings_.filterRadius, static_cast<float>(cube.resolution));
  }
  forward.set("uPointShadowMap", std::span<const int>(units));
  forward.set("uPointShadowParams", std::span<const glm::vec4>(params));
}

}  // namespace bounce
