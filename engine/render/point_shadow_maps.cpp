#include "render/point_shadow_maps.h"

#include "render/gpu_scene.h"
#include "render/shadow_casters.h"
#include "render/texture_units.h"

namespace bounce {

namespace {

int cubeResolution(const ShadowSettings& settings, const Light& light, const Box& sceneBox) {
  return settings.resolution > 0
             ? settings.resolution
             : defaultShadowResolution(light.position, sceneBox, 2.0f, 256, 1024);
}

}  // namespace

int PointShadowMaps::add(const Light& light, const Box& sceneBox) {
  if (static_cast<int>(cubes_.size()) == kMaxPointShadows) return -1;
  const int resolution = cubeResolution(settings_, light, sceneBox);
  cubes_.push_back({light, gl::DepthCubeMap(resolution), resolution, 1.0f, true, {}});
  return static_cast<int>(cubes_.size()) - 1;
}

void PointShadowMaps::assign(int slot, const Light& light, const Box& sceneBox) {
  if (slot == static_cast<int>(cubes_.size())) {
    add(light, sceneBox);
    return;
  }
  Cube& cube = cubes_.at(static_cast<std::size_t>(slot));
  const int resolution = cubeResolution(settings_, light, sceneBox);
  if (resolution != cube.resolution) {
    cube.texture = gl::DepthCubeMap(resolution);
    cube.resolution = resolution;
  }
  cube.light = light;
  cube.used = true;
  for (ShadowMapStamp& face : cube.drawn) face.invalidate();
}

ShadowDrawCount PointShadowMaps::render(const GpuScene& scene, const ViewVolume& view,
                                        gl::Program& depthProgram, gl::DepthTarget& target) {
  const Box sceneBox = scene.bounds();
  ShadowDrawCount count;
  for (Cube& cube : cubes_) {
    if (!cube.used) continue;
    for (int face = 0; face < 6; ++face) {
      const ShadowView faceView =
          cubeFaceShadowView(cube.light.position, face, sceneBox, cube.resolution);
      cube.far = faceView.far;
      if (!view.mayReach(faceView.viewProjection, sceneBox)) continue;
      ShadowMapStamp& drawn = cube.drawn[static_cast<std::size_t>(face)];
      if (drawn.matches(faceView.viewProjection, scene.instances())) continue;
      drawn.set(faceView.viewProjection, scene.instances());
      target.bind(cube.texture, face);
      count += {1, drawShadowCasters(scene, faceView, cube.light.position, depthProgram)};
    }
  }
  return count;
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
