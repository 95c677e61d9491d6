#include "render/area_shadow_maps.h"

#include <algorithm>

#include "gl/draw_state.h"
#include "gl/texture.h"
#include "render/texture_units.h"

namespace bounce {
void AreaShadowMaps::add(const GpuScene& scene, std::vector<std::string>& warnings) {
  if (!settings_.enabled) return;
  const std::vector<AreaLight>& lights = scene.areaLights().lights;
  for (const uint32_t i : pickShadowedAreaLights(lights, kMaxAreaShadows)) {
    Cube cube;
    cube.index = i;
    cube.light = lights[i];
    cubes_.push_back(std::move(cube));
  }
  if (lights.size() > cubes_.size())
    warnings.push_back(std::to_string(lights.size() - cubes_.size()) + " area lights beyond the " +
                       std::to_string(kMaxAreaShadows) +
                       " most powerful have no shadow map: they shadow only static surfaces of a "
                       "bake with their visibility (visibility.bin)");
  if (!cubes_.empty()) sampler_.emplace();
  place(scene);
}

void AreaShadowMaps::place(const GpuScene& scene) {
  emitterVersion_ = scene.emitterVersion();
  const AreaLightSet& set = scene.areaLights();
  const Box sceneBox = scene.bounds();
  for (Cube& cube : cubes_) {
    // A moved instance is cut into the same lights (the rule is rigid-motion invariant) unless
    // rounding changes a bit-equal edge: then the cube keeps its old light.
    if (cube.index >= set.lights.size() || set.lights[cube.index].instance != cube.light.instance)
      continue;
    cube.light = set.lights[cube.index];
    // The light's own instance is left out of its map (render), so its centre can see past it.
    cube.origin = cube.light.centre;
    cube.points = samplePoints(set, cube.index, kAreaShadowSamples);
    cube.rows = glm::ivec2(static_cast<int>(cube.light.first),
                           static_cast<int>(cube.light.first + cube.light.count));
    int resolution = settings_.resolution;
    // The point lights' rule (shadow_map_geometry.h): texels no larger than 1/2048 of the
    // scene's diagonal at the distance of its centre.
    if (resolution <= 0)
      resolution = defaultShadowResolution(cube.origin, sceneBox, 2.0f, 256, 1024);
    if (resolution != cube.resolution) {
      cube.texture.reset();
      cube.texture.emplace(resolution);
      cube.dynamicTexture.reset();
      cube.resolution = resolution;
    }
    if (dynamicCubes_ && !cube.dynamicTexture) cube.dynamicTexture.emplace(resolution);
  }
}

bool AreaShadowMaps::setDynamicCasterCubes(bool enabled) {
  if (enabled &&
      gl::Texture2D::maxFragmentUnits() < TextureUnit::kAreaDynamicShadow0 + kMaxAreaShadows)
    return false;
  dynamicCubes_ = enabled;
  for (Cube& cube : cubes_) {
    cube.dynamicTexture.reset();
    if (enabled && cube.resolution > 0) cube.dynamicTexture.emplace(cube.resolution);
  }
  return true;
}

ShadowDrawCount AreaShadowMaps::render(const GpuScene& scene, const ViewVolume& view,
                                       gl::Program& depthProgram, gl::DepthTarget& target) {
  ShadowDrawCount count;
  if (cubes_.empty() || !allCastersNeeded_) return count;
  if (scene.emitterVersion() != emitterVersion_) place(scene);
  const Box sceneBox = scene.bounds();
  for (Cube& cube : cubes_) {
    for (int face = 0; face < 6; ++face) {
      const ShadowView faceView = cubeFaceShadowView(cube.origin, face, sceneBox, cube.resolution);
      cube.far = faceView.far;
      const bool reaches = view.mayReach(faceView.viewProjection, sceneBox);
      // Every caster, then (dynamicCubes_) the dynamic ones alone.
      for (const bool dynamicOnly : {false, true}) {
        if (dynamicOnly && !(dynamicCubes_ && cube.dynamicTexture)) break;
        target.bind(dynamicOnly ? *cube.dynamicTexture : *cube.texture, face);
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
        const std::span<const GpuInstance> instances = scene.instances();
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
  for (int slot = 0; slot < kMaxAreaShadows; ++slot) {
    forward.set("uAreaShadowMap" + std::to_string(slot), TextureUnit::kAreaShadow0 + slot);
    // Unused, they share the all-caster cubes' units (the same sampler type).
    forward.set(
        "uAreaDynamicShadowMap" + std::to_string(slot),
        (dynamicCubes_ ? TextureUnit::kAreaDynamicShadow0 : TextureUnit::kAreaShadow0) + slot);
  }
  forward.set("uAreaDynamicShadows", dynamicCubes_ ? 1 : 0);
  for (std::size_t slot = 0; slot < cubes_.size(); ++slot) {
    const Cube& cube = cubes_[slot];
    const int unit = TextureUnit::kAreaShadow0 + static_cast<int>(slot);
    cube.texture->bind(unit);
    sampler_->bind(unit);
    if (dynamicCubes_ && cube.dynamicTexture) {
      const int dynamicUnit = TextureUnit::kAreaDynamicShadow0 + static_cast<int>(slot);
      cube.dynamicTexture->bind(dynamicUnit);
      sampler_->bind(dynamicUnit);
    }
    origins[slot] = cube.origin;
    // The light's radius bounds the blocker search's reach (shaders/shadow_area.glsl, d_min).
    params[slot] = glm::vec4(cube.far, static_cast<float>(cube.resolution), cube.light.radius,
                             settings_.filterRadius);
    rows[slot] = glm::vec2(cube.rows);
    normals[slot] = glm::vec4(cube.light.normal, cube.light.doubleSided ? 1.0f : 0.0f);
    std::copy(cube.points.begin(), cube.points.end(),
              points.begin() + static_cast<std::ptrdiff_t>(slot * kAreaShadowSamples));
  }
  forward.set("uAreaShadowCount", allCastersNeeded_ ? static_cast<int>(cubes_.size()) : 0);
  forward.set("uAreaShadowOrigin", std::span<const glm::vec3>(origins));
  forward.set("uAreaShadowParams", std::span<const glm::vec4>(params));
  forward.set("uAreaShadowRows", std::span<const glm::vec2>(rows));
  forward.set("uAreaShadowNormal", std::span<const glm::vec4>(normals));
  forward.set("uAreaShadowPoints", std::span<const glm::vec3>(points));
}

}  // namespace bounce
