#include "render/area_shadow_maps.h"

#include <algorithm>

#include "gl/draw_state.h"
#include "gl/texture.h"
#include "render/gpu_scene.h"
#include "render/shadow_receivers.h"
#include "render/texture_units.h"

namespace bounce {
void AreaShadowMaps::add(const GpuScene& scene) {
  const std::vector<AreaLight>& lights = scene.areaLights().lights;
  if (!settings_.enabled || lights.empty()) return;
  slots_ = std::min(areaShadowSlotCapacity(gl::DepthTextureArray::maxLayers()),
                    static_cast<int>(lights.size()));
  cubes_.resize(static_cast<std::size_t>(slots_));
  // One resolution for every slot: the point lights' rule (shadow_map_geometry.h: texels no
  // larger than 1/2048 of the scene's diagonal at the distance of its centre) at the light
  // that needs the most.
  resolution_ = settings_.resolution;
  if (resolution_ <= 0)
    for (const AreaLight& light : lights)
      resolution_ = std::max(
          resolution_, defaultShadowResolution(light.centre, scene.bounds(), 2.0f, 256, 1024));
  maps_.emplace(resolution_, 6 * slots_);
  if (dynamicCubes_) dynamic_.emplace(resolution_, 6 * slots_);
  sampler_.emplace();
}

AreaShadowReceivers AreaShadowMaps::receivers(const GpuScene& scene, const ViewVolume& view) const {
  AreaShadowReceivers where;
  // Static surfaces read the all-caster cubes of every light without baked visibility.
  static_cast<ShadowReceivers&>(where) = shadowReceivers(
      scene, view, allCastersNeeded_ && bakedVisibilityLights_ < scene.areaLights().lights.size(),
      view.eye);
  where.bakedVisibilityLights = bakedVisibilityLights_;
  where.bakedDirectSkipped = bakedDirectSkipped_;
  return where;
}

void AreaShadowMaps::assign(const GpuScene& scene, const std::vector<uint32_t>& lights) {
  const auto chosen = [&](std::size_t index) {
    return std::find(lights.begin(), lights.end(), index) != lights.end();
  };
  for (Cube& cube : cubes_)
    if (cube.occupied && !chosen(cube.index)) cube.occupied = false;
  for (const uint32_t l : lights) {
    if (std::any_of(cubes_.begin(), cubes_.end(),
                    [&](const Cube& c) { return c.occupied && c.index == l; }))
      continue;
    const auto free =
        std::find_if(cubes_.begin(), cubes_.end(), [](const Cube& c) { return !c.occupied; });
    if (free == cubes_.end()) break;  // cannot happen: at most slots_ are chosen
    *free = Cube{};
    free->occupied = true;
    free->index = l;
    free->light = scene.areaLights().lights[l];
    place(scene, *free);
  }
}

void AreaShadowMaps::place(const GpuScene& scene, Cube& cube) const {
  const AreaLightSet& set = scene.areaLights();
  // A moved instance is cut into the same lights (the rule is rigid-motion invariant) unless
  // rounding changes a bit-equal edge: then the cube keeps its old light.
  if (cube.index >= set.lights.size() || set.lights[cube.index].instance != cube.light.instance)
    return;
  cube.light = set.lights[cube.index];
  // The light's own instance is left out of its map (render), so its centre can see past it.
  cube.origin = cube.light.centre;
  cube.points = samplePoints(set, cube.index, kAreaShadowSamples);
  cube.rows = glm::ivec2(static_cast<int>(cube.light.first),
                         static_cast<int>(cube.light.first + cube.light.count));
  cube.faces.fill(FaceState::Stale);
}

bool AreaShadowMaps::setDynamicCasterCubes(bool enabled) {
  if (enabled && gl::Texture2D::maxFragmentUnits() <= TextureUnit::kAreaDynamicShadow0)
    return false;
  dynamicCubes_ = enabled;
  dynamic_.reset();
  if (enabled && maps_) dynamic_.emplace(resolution_, 6 * slots_);
  for (Cube& cube : cubes_) cube.faces.fill(FaceState::Stale);
  return true;
}

ShadowDrawCount AreaShadowMaps::render(const GpuScene& scene, const ViewVolume& view, float floor,
                                       gl::Program& depthProgram, gl::DepthTarget& target) {
  ShadowDrawCount count;
  if (slots_ == 0 || !allCastersNeeded_) {
    choice_ = {};
    return count;
  }
  const std::span<const GpuInstance> instances = scene.instances();
  // Lights re-cut (an emitter moved) or any instance moved: every face is out of date.
  bool moved = scene.emitterVersion() != emitterVersion_ || drawnModels_.size() != instances.size();
  for (std::size_t i = 0; !moved && i < instances.size(); ++i)
    moved = instances[i].model != drawnModels_[i];
  if (moved) {
    dynamicCasters_.clear();
    for (const GpuInstance& instance : instances)
      if (instance.mobility == Mobility::Dynamic && !instance.worldBox.empty())
        dynamicCasters_.push_back(instance.worldSphere);
    tooManyDynamicCasters_ = dynamicCasters_.size() > kMaxDynamicCasters;
    if (tooManyDynamicCasters_) dynamicCasters_.clear();
    if (scene.emitterVersion() != emitterVersion_)
      for (Cube& cube : cubes_)
        if (cube.occupied) place(scene, cube);
    for (Cube& cube : cubes_) cube.faces.fill(FaceState::Stale);
    emitterVersion_ = scene.emitterVersion();
    drawnModels_.clear();
    for (const GpuInstance& instance : instances) drawnModels_.push_back(instance.model);
  }
  std::vector<uint32_t> held;
  for (const Cube& cube : cubes_)
    if (cube.occupied) held.push_back(static_cast<uint32_t>(cube.index));
  const std::vector<float> contribution =
      areaLightContributions(scene.areaLights(), receivers(scene, view), floor);
  // The floor is in the contributions: a light under it everywhere the cubes are read has 0.
  choice_ = chooseShadowedLights(contribution, slots_, 0.0f, held);
  assign(scene, choice_.lights);

  const Box sceneBox = scene.bounds();
  for (std::size_t slot = 0; slot < cubes_.size(); ++slot) {
    Cube& cube = cubes_[slot];
    if (!cube.occupied) continue;
    for (int face = 0; face < 6; ++face) {
      const ShadowView faceView = cubeFaceShadowView(cube.origin, face, sceneBox, resolution_);
      cube.far = faceView.far;
      const bool reaches = view.mayReach(faceView.viewProjection, sceneBox);
      FaceState& state = cube.faces[static_cast<std::size_t>(face)];
      // Drawn stays valid out of view; cleared must be drawn once it can be seen.
      if (state == FaceState::Drawn || (state == FaceState::Cleared && !reaches)) continue;
      state = reaches ? FaceState::Drawn : FaceState::Cleared;
      // Every caster, then (dynamicCubes_) the dynamic ones alone.
      for (const bool dynamicOnly : {false, true}) {
        if (dynamicOnly && !dynamic_) break;
        target.bind(dynamicOnly ? *dynamic_ : *maps_, 6 * static_cast<int>(slot) + face);
        gl::clearDepth();
        if (!reaches) continue;
        // drawShadowCasters (shadow_casters.h) less the light's own instance: its surface passes
        // through the map's origin and would hide everything from a double-sided light.
        gl::setDepthTest(true);
        gl::setBackFaceCulling(false);
        depthProgram.set("uViewProjection", faceView.viewProjection);
        depthProgram.set("uLightPosition", cube.origin);
        depthProgram.set("uFar", faceView.far);
        const Frustum frustum(faceView.viewProjection);
        ++count.views;
        for (std::size_t i = 0; i < instances.size(); ++i) {
          if (i == cube.light.instance || !frustum.overlaps(instances[i].worldBox)) continue;
          if (dynamicOnly && instances[i].mobility != Mobility::Dynamic) continue;
          scene.draw(instances[i], depthProgram);
          ++count.casters;
        }
      }
    }
  }
  return count;
}

void AreaShadowMaps::bind(gl::Program& forward) const {
  std::vector<glm::vec3> origins(kMaxAreaShadows, glm::vec3(0.0f));
  std::vector<glm::vec4> params(kMaxAreaShadows, glm::vec4(1.0f));
  std::vector<glm::vec2> rows(kMaxAreaShadows, glm::vec2(0.0f));
  std::vector<glm::vec4> normals(kMaxAreaShadows, glm::vec4(0.0f));
  std::vector<glm::vec3> points(static_cast<std::size_t>(kMaxAreaShadows * kAreaShadowSamples),
                                glm::vec3(0.0f));
  forward.set("uAreaShadowMaps", TextureUnit::kAreaShadow0);
  // Unused, it shares the all-caster array's unit (the same sampler type).
  forward.set("uAreaDynamicShadowMaps",
              dynamic_ ? TextureUnit::kAreaDynamicShadow0 : TextureUnit::kAreaShadow0);
  forward.set("uAreaDynamicShadows", dynamic_ ? 1 : 0);
  if (maps_) {
    maps_->bind(TextureUnit::kAreaShadow0);
    sampler_->bind(TextureUnit::kAreaShadow0);
  }
  if (dynamic_) {
    dynamic_->bind(TextureUnit::kAreaDynamicShadow0);
    sampler_->bind(TextureUnit::kAreaDynamicShadow0);
  }
  int count = 0;  // one past the last occupied slot (empty ones keep rows (0, 0): no light)
  for (std::size_t slot = 0; slot < cubes_.size(); ++slot) {
    const Cube& cube = cubes_[slot];
    if (!cube.occupied) continue;
    count = static_cast<int>(slot) + 1;
    origins[slot] = cube.origin;
    // The light's radius bounds the blocker search's reach (shaders/shadow_area.glsl, d_min).
    params[slot] = glm::vec4(cube.far, static_cast<float>(resolution_), cube.light.radius,
                             settings_.filterRadius);
    rows[slot] = glm::vec2(cube.rows);
    normals[slot] = glm::vec4(cube.light.normal, cube.light.doubleSided ? 1.0f : 0.0f);
    std::copy(cube.points.begin(), cube.points.end(),
              points.begin() + static_cast<std::ptrdiff_t>(slot * kAreaShadowSamples));
  }
  forward.set("uAreaShadowCount", allCastersNeeded_ ? count : 0);
  forward.set("uAreaShadowOrigin", std::span<const glm::vec3>(origins));
  forward.set("uAreaShadowParams", std::span<const glm::vec4>(params));
  forward.set("uAreaShadowRows", std::span<const glm::vec2>(rows));
  forward.set("uAreaShadowNormal", std::span<const glm::vec4>(normals));
  forward.set("uAreaShadowPoints", std::span<const glm::vec3>(points));
  std::vector<glm::vec4> casters(kMaxDynamicCasters, glm::vec4(0.0f));
  std::copy(dynamicCasters_.begin(), dynamicCasters_.end(), casters.begin());
  forward.set("uDynamicCasterCount",
              tooManyDynamicCasters_ ? -1 : static_cast<int>(dynamicCasters_.size()));
  forward.set("uDynamicCasters", std::span<const glm::vec4>(casters));
}

}  // namespace bounce
