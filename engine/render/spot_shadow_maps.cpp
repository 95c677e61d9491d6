#include "render/spot_shadow_maps.h"

#include "render/gpu_scene.h"
#include "render/shadow_casters.h"
#include "render/texture_units.h"

namespace bounce {

int SpotShadowMaps::add(const Light& light, const Box& sceneBox) {
  if (static_cast<int>(maps_.size()) == kMaxSpotShadows) return -1;
  const ShadowView view = spotShadowViewFor(light, sceneBox, settings_);
  maps_.push_back({light, gl::DepthTexture2D(view.resolution, view.resolution), view, true, {}});
  return static_cast<int>(maps_.size()) - 1;
}

void SpotShadowMaps::assign(int slot, const Light& light, const Box& sceneBox) {
  if (slot == static_cast<int>(maps_.size())) {
    add(light, sceneBox);
    return;
  }
  Map& map = maps_.at(static_cast<std::size_t>(slot));
  const ShadowView view = spotShadowViewFor(light, sceneBox, settings_);
  if (view.resolution != map.view.resolution)
    map.texture = gl::DepthTexture2D(view.resolution, view.resolution);
  map.light = light;
  map.view = view;
  map.used = true;
  map.drawn.invalidate();
}

ShadowDrawCount SpotShadowMaps::render(const GpuScene& scene, const ViewVolume& view,
                                       gl::Program& depthProgram, gl::DepthTarget& target) {
  const Box sceneBox = scene.bounds();
  ShadowDrawCount count;
  for (Map& map : maps_) {
    if (!map.used) continue;
    // Dynamic instances move: the reach (far) follows the scene's current bounds.
    map.view =
        spotShadowView(map.light, sceneBox, map.view.resolution, settings_.filterRadius + 2.0f);
    if (!view.mayReach(map.view.viewProjection, sceneBox)) continue;
    if (map.drawn.matches(map.view.viewProjection, scene.instances())) continue;
    map.drawn.set(map.view.viewProjection, scene.instances());
    target.bind(map.texture);
    count += {1, drawShadowCasters(scene, map.view, map.light.position, depthProgram)};
  }
  return count;
}

void SpotShadowMaps::bind(gl::Program& forward) const {
  std::vector<int> units;
  std::vector<glm::mat4> matrices;
  std::vector<glm::vec4> params;
  for (int slot = 0; slot < kMaxSpotShadows; ++slot)
    units.push_back(TextureUnit::kSpotShadow0 + slot);
  for (std::size_t slot = 0; slot < maps_.size(); ++slot) {
    const Map& map = maps_[slot];
    map.texture.bind(TextureUnit::kSpotShadow0 + static_cast<int>(slot));
    matrices.push_back(map.view.viewProjection);
    params.emplace_back(map.view.texelAngle, map.view.far, settings_.filterRadius,
                        static_cast<float>(map.view.resolution));
  }
  forward.set("uSpotShadowMap", std::span<const int>(units));
  forward.set("uSpotShadowMatrix", std::span<const glm::mat4>(matrices));
  forward.set("uSpotShadowParams", std::span<const glm::vec4>(params));
}

}  // namespace bounce
