#include "render/shadow_pass.h"

#include "gl/draw_state.h"
#include "render/texture_units.h"

namespace bounce {

ShadowPass::ShadowPass(const GpuScene& scene, const PunctualLights& lights,
                       const ShadowSettings& settings, const std::filesystem::path& shaderDir,
                       std::vector<std::string>& warnings)
    : settings_(settings),
      depth_(shaderDir / "shadow_depth.vert", shaderDir / "shadow_depth.frag"),
      lightSlot_(lights.size(), -1),
      spot_(settings),
      point_(settings),
      directional_(settings, shaderDir),
      area_(settings) {
  if (!settings.enabled) return;
  const Box sceneBox = scene.bounds();
  int unshadowed = 0;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const Light& light = lights.light(i);
    if (light.type == LightType::Spot) lightSlot_[i] = spot_.add(light, sceneBox);
    if (light.type == LightType::Point) lightSlot_[i] = point_.add(light, sceneBox);
    if (light.type == LightType::Directional) lightSlot_[i] = directional_.add(light);
    if (lightSlot_[i] < 0) ++unshadowed;
  }
  area_.add(scene);
  if (unshadowed > 0)
    warnings.push_back(std::to_string(unshadowed) + " lights beyond the first " +
                       std::to_string(kMaxSpotShadows) + " spot, " +
                       std::to_string(kMaxPointShadows) +
                       " point and 1 directional light cast no shadows");
}

void ShadowPass::setLight(std::size_t index, const Light& light) {
  const int slot = index < lightSlot_.size() ? lightSlot_[index] : -1;
  if (slot < 0) return;
  if (light.type == LightType::Spot) spot_.setLight(slot, light);
  if (light.type == LightType::Point) point_.setLight(slot, light);
  if (light.type == LightType::Directional) directional_.setLight(light);
}

void ShadowPass::render(const GpuScene& scene, const ViewVolume& view, const Camera& camera,
                        float aspect, float areaFloor) {
  lastFrame_ = {};
  if (!settings_.enabled) return;
  lastFrame_ += spot_.render(scene, view, depth_, target_);
  lastFrame_ += point_.render(scene, view, depth_, target_);
  lastFrame_ += directional_.render(scene, camera, aspect, target_);
  lastFrame_ += area_.render(scene, view, areaFloor, depth_, target_);
  gl::checkErrors("shadow pass");
}

void ShadowPass::bind(gl::Program& forward) const {
  forward.set("uShadowFilter", settings_.filter == ShadowFilter::Poisson ? 1 : 0);
  spot_.bind(forward);
  point_.bind(forward);
  directional_.bind(forward);
  area_.bind(forward);
}

}  // namespace bounce
