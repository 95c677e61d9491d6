#include "render/shadow_pass.h"

#include <algorithm>

#include "gl/draw_state.h"
#include "gl/gpu_pass_timers.h"
#include "render/area_shadow_maps.h"
#include "render/directional_shadow_maps.h"
#include "render/gpu_scene.h"
#include "render/point_shadow_maps.h"
#include "render/punctual_lights.h"
#include "render/punctual_shadow_budget.h"
#include "render/shader_constants.h"
#include "render/shadow_receivers.h"
#include "render/spot_shadow_maps.h"
#include "render/texture_units.h"

namespace bounce {

struct ShadowPass::Maps {
  Maps(const ShadowSettings& settings, const std::filesystem::path& shaderDir)
      : spot(settings), point(settings), directional(settings, shaderDir), area(settings) {}
  SpotShadowMaps spot;
  PointShadowMaps point;
  DirectionalShadowMaps directional;
  AreaShadowMaps area;
};

ShadowPass::~ShadowPass() = default;

bool ShadowPass::setDynamicCasterCubes(bool enabled) {
  return maps_->area.setDynamicCasterCubes(enabled);
}

void ShadowPass::setAreaCubesNeeded(bool needed) {
  maps_->area.setAllCasterCubesNeeded(needed);
}

void ShadowPass::setAreaBake(std::size_t bakedVisibilityLights, bool bakedDirectSkipped) {
  maps_->area.setBakedVisibilityLights(bakedVisibilityLights);
  maps_->area.setBakedDirectSkipped(bakedDirectSkipped);
}

const ShadowChoice& ShadowPass::areaShadowChoice() const {
  return maps_->area.lastChoice();
}

int ShadowPass::areaShadowSlots() const {
  return maps_->area.slots();
}

ShadowPass::ShadowPass(const GpuScene& scene, const PunctualLights& lights,
                       const ShadowSettings& settings, const std::filesystem::path& shaderDir,
                       std::vector<std::string>& warnings)
    : settings_(settings),
      depth_(shaderDir / "shadow_depth.vert", shaderDir / "shadow_depth.frag", shaderConstants()),
      lightSlot_(lights.size(), -1),
      maps_(std::make_unique<Maps>(settings, shaderDir)) {
  if (!settings.enabled) return;
  // Until the first frame chooses, the maps go to the first lights of each kind.
  const Box sceneBox = scene.bounds();
  int unshadowed = 0;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const Light& light = lights.light(i);
    if (light.type == LightType::Spot) lightSlot_[i] = maps_->spot.add(light, sceneBox);
    if (light.type == LightType::Point) lightSlot_[i] = maps_->point.add(light, sceneBox);
    if (light.type == LightType::Directional) lightSlot_[i] = maps_->directional.add(light);
    if (lightSlot_[i] < 0) ++unshadowed;
    // The maps each kind has: one past the highest slot handed out.
    int& maps = light.type == LightType::Spot    ? slots_.spot
                : light.type == LightType::Point ? slots_.point
                                                 : slots_.directional;
    maps = std::max(maps, lightSlot_[i] + 1);
  }
  maps_->area.add(scene);
  crowded_ = unshadowed > 0;
  if (unshadowed > 0)
    warnings.push_back(std::to_string(unshadowed) + " punctual lights more than the maps (" +
                       std::to_string(kMaxSpotShadows) + " spot, " +
                       std::to_string(kMaxPointShadows) +
                       " point, 1 directional): each frame the maps go to the lights that bring "
                       "the most light to the view and its dynamic objects; the others cast no "
                       "shadow map's shadows");
}

bool ShadowPass::choosePunctualMaps(const GpuScene& scene, const PunctualLights& lights,
                                    const ViewVolume& view, float floor) {
  // Spot and point lights the bake names where every static surface reads it (setStaticVisibility-
  // Baked): ranked by the dynamic instances alone.
  std::vector<uint8_t> baked(lights.size(), 0);
  bool anyBaked = false, anyUnbaked = false;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    baked[i] =
        staticBaked_ && lights.bakedIndex(i) >= 0 && lights.light(i).type != LightType::Directional
            ? 1
            : 0;
    anyBaked = anyBaked || baked[i] != 0;
    anyUnbaked = anyUnbaked || baked[i] == 0;
  }
  // Every light has its map and none can do without: nothing to choose (and no view points to
  // find each frame).
  if (!crowded_ && !anyBaked) return false;
  std::vector<Light> current;
  std::vector<glm::vec3> power;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    current.push_back(lights.light(i));
    power.push_back(lights.drawnPower(i));
  }
  const std::vector<float> contribution = punctualLightContributions(
      current, power, shadowReceivers(scene, view, anyUnbaked, view.eye), floor, baked);
  std::vector<int> slot =
      assignPunctualShadowSlots(current, contribution, slots_, 0.0f, lightSlot_);
  // An unchosen light keeps a map no other light took, unless it needs none: a baked light with
  // no dynamic instance in its reach reads the bake alone, and its map is not drawn.
  for (std::size_t i = 0; i < slot.size(); ++i)
    if (baked[i] && !(contribution[i] > 0.0f)) slot[i] = -1;
  if (slot == lightSlot_) return false;
  const Box sceneBox = scene.bounds();
  std::vector<bool> spotUsed(static_cast<std::size_t>(slots_.spot), false);
  std::vector<bool> pointUsed(static_cast<std::size_t>(slots_.point), false);
  bool directionalUsed = false;
  for (std::size_t i = 0; i < current.size(); ++i) {
    if (slot[i] < 0) continue;
    const Light& light = current[i];
    const bool moved = slot[i] != lightSlot_[i];
    if (light.type == LightType::Spot) {
      spotUsed[static_cast<std::size_t>(slot[i])] = true;
      if (moved) maps_->spot.assign(slot[i], light, sceneBox);
    }
    if (light.type == LightType::Point) {
      pointUsed[static_cast<std::size_t>(slot[i])] = true;
      if (moved) maps_->point.assign(slot[i], light, sceneBox);
    }
    if (light.type == LightType::Directional) {
      directionalUsed = true;
      if (moved) maps_->directional.assign(light);
    }
  }
  for (std::size_t s = 0; s < spotUsed.size(); ++s)
    if (!spotUsed[s]) maps_->spot.release(static_cast<int>(s));
  for (std::size_t s = 0; s < pointUsed.size(); ++s)
    if (!pointUsed[s]) maps_->point.release(static_cast<int>(s));
  if (!directionalUsed && slots_.directional > 0) maps_->directional.release();
  lightSlot_ = slot;
  return true;
}

void ShadowPass::setLight(std::size_t index, const Light& light) {
  const int slot = index < lightSlot_.size() ? lightSlot_[index] : -1;
  if (slot < 0) return;
  if (light.type == LightType::Spot) maps_->spot.setLight(slot, light);
  if (light.type == LightType::Point) maps_->point.setLight(slot, light);
  if (light.type == LightType::Directional) maps_->directional.setLight(light);
}

bool ShadowPass::render(const GpuScene& scene, const PunctualLights& lights, const ViewVolume& view,
                        const Camera& camera, float aspect, float floor,
                        gl::GpuPassTimers* timers) {
  lastFrame_ = {};
  if (!settings_.enabled) return false;
  const bool slotsChanged = choosePunctualMaps(scene, lights, view, floor);
  using Timed = gl::GpuPassTimers::Scope;
  {
    const Timed timed(timers, "shadow: spot maps");
    lastFrame_ += maps_->spot.render(scene, view, depth_, target_);
  }
  {
    const Timed timed(timers, "shadow: point cubes");
    lastFrame_ += maps_->point.render(scene, view, depth_, target_);
  }
  {
    const Timed timed(timers, "shadow: directional cascades");
    lastFrame_ += maps_->directional.render(scene, camera, aspect, target_);
  }
  {
    const Timed timed(timers, "shadow: area-light cubes");
    lastFrame_ += maps_->area.render(scene, view, floor, depth_, target_);
  }
  gl::checkErrors("shadow pass");
  return slotsChanged;
}

void ShadowPass::bind(gl::Program& forward) const {
  forward.set("uShadowFilter", settings_.filter == ShadowFilter::Poisson ? 1 : 0);
  maps_->spot.bind(forward);
  maps_->point.bind(forward);
  maps_->directional.bind(forward);
  maps_->area.bind(forward);
}

}  // namespace bounce
