#include "render/spot_shadow_maps.h"

#include <cmath>

#include "render/shadow_casters.h"
#include "render/texture_units.h"

namespace bounce {
namespace {

// Texels between the cone's rim and the map's edge: the filter radius plus the bilinear tap.
float marginTexels(const ShadowSettings& settings) {
  return settings.filterRadius + 2.0f;
}

}  // namespace

int SpotShadowMaps::add(const Light& light, const Box& sceneBox) {
  if (static_cast<int>(maps_.size()) == kMaxSpotShadows) return -1;
  int resolution = settings_.resolution;
  if (resolution <= 0) {
    const float span = 2.0f * std::tan(spotMapHalfAngle(light, 2048, marginTexels(settings_)));
    resolution = defaultShadowResolution(light.position, sceneBox, span, 512, 2048);
  }
  maps_.push_back({light, gl::DepthTexture2D(resolution, resolution),
                   spotShadowView(light, sceneBox, resolution, marginTexels(settings_))});
  return static_cast<int>(maps_.size()) - 1;
}

void SpotShadowMaps::render(const GpuScene& scene, const Box& visibleBox, gl::Program& depthProgram,
                            gl::DepthTarget& target) {
  const Box sceneBox = scene.bounds();
  for (Map& map : maps_) {
    // Dynamic instances move: the reach (far) follows the scene's current bounds.
    map.view = spotShadowView(map.light, sceneBox, map.view.resolution, marginTexels(settings_));
    if (!Frustum(map.view.viewProjection).overlaps(visibleBox)) continue;
    target.bind(map.texture);
    drawShadowCasters(scene, map.view, map.light.position, depthProgram);
  }
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
