// The shadow pass: before the lit pass, renders a depth map for each shadowed light whose
// light can reach what the camera sees (spot: spot_shadow_maps.h; point: point_shadow_maps.h;
// directional: cascades fitted to the camera, directional_shadow_maps.h; area lights: cubes for
// soft shadows, area_shadow_maps.h), then hands the maps to the lit pass. Which light has which map
// is lightSlots()[i], stored with the light in the light table (render/light_table.h): the slot
// among its kind's maps, or −1 (unshadowed). A kind with more lights than maps gives them each
// frame to the lights that bring the most light where the maps are read
// (punctual_shadow_budget.h; the area cubes: area_shadow_budget.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <memory>
#include <span>

#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/punctual_shadow_budget.h"
#include "render/shadow_settings.h"
#include "scene/scene.h"

namespace bounce {

class GpuScene;
class PunctualLights;
struct ShadowChoice;
struct ViewVolume;
namespace gl {
class GpuPassTimers;  // gl/gpu_pass_timers.h
}  // namespace gl

class ShadowPass {
 public:
  ShadowPass(const GpuScene& scene, const PunctualLights& lights, const ShadowSettings& settings,
             const std::filesystem::path& shaderDir, std::vector<std::string>& warnings);
  ~ShadowPass();
  ShadowPass(const ShadowPass&) = delete;
  ShadowPass& operator=(const ShadowPass&) = delete;

  // `view`: what the camera can see; maps that cannot reach it are not rendered. `camera` and
  // the image's `aspect`: what the directional cascades are fitted to. `floor` (W/m²): a light
  // bringing less where the maps are read gets none (shadow_choice.h). `lights`: the punctual
  // lights as drawn now. Returns true when lightSlots() changed (the light table holds them).
  // `timers` (may be null) times each kind's maps as a pass of its own.
  bool render(const GpuScene& scene, const PunctualLights& lights, const ViewVolume& view,
              const Camera& camera, float aspect, float floor, gl::GpuPassTimers* timers = nullptr);
  // Binds the maps and sets every shadow uniform of the forward program.
  void bind(gl::Program& forward) const;
  // AreaShadowMaps::setDynamicCasterCubes: false when the driver cannot.
  bool setDynamicCasterCubes(bool enabled);
  void setAreaCubesNeeded(bool needed);
  // AreaShadowMaps::setBakedVisibilityLights and setBakedDirectSkipped.
  void setAreaBake(std::size_t bakedVisibilityLights, bool bakedDirectSkipped);
  // Whether every static instance reads the bake's visibility (a lightmap region, or corners:
  // LightmapPass::visibilityOnEveryStaticInstance). Then a static spot or point light the bake
  // names needs a map only for what moves: it gets one while a dynamic instance is in its reach
  // (an all-caster map: the dynamic receivers need the static casters' shadows, and static
  // surfaces take min(V_map, V_baked)), and none otherwise. A directional light keeps its
  // cascades over the view: the sun's hard shadows across a room are where a texel's blur shows
  // (docs/shadows.md, the sunlit room: 1.23% with cascades and baked V, 7.50% baked V alone).
  void setStaticVisibilityBaked(bool baked) { staticBaked_ = baked; }
  // Which area lights have a cube this frame and what the others bring; the most cubes at once.
  const ShadowChoice& areaShadowChoice() const;
  int areaShadowSlots() const;
  // Punctual light `index` moved, turned or changed power (its kind stays): its map follows.
  void setLight(std::size_t index, const Light& light);
  // Per punctual light: its map's slot among its kind's maps, −1 for none (the first lights of
  // each kind until the first render chooses).
  std::span<const int> lightSlots() const { return lightSlot_; }
  // What the last render() drew (culling's effect).
  const ShadowDrawCount& lastFrame() const { return lastFrame_; }

 private:
  // Gives this frame's maps to the punctual lights (punctual_shadow_budget.h): by contribution
  // when some kind has more lights than maps or some light's visibility is baked on every static
  // surface; true when a light's slot changed.
  bool choosePunctualMaps(const GpuScene& scene, const PunctualLights& lights,
                          const ViewVolume& view, float floor);

  ShadowSettings settings_;
  PunctualShadowSlots slots_;  // maps of each kind: at most the kind's maximum and its lights
  bool crowded_ = false;       // some kind has more lights than maps
  bool staticBaked_ = false;   // every static instance reads the bake's visibility
  gl::Program depth_;
  gl::DepthTarget target_;
  std::vector<int> lightSlot_;  // per punctual light: its map's slot in its kind, −1 for none
  struct Maps;  // each kind's maps (spot, point, directional, area cubes): shadow_pass.cpp
  std::unique_ptr<Maps> maps_;
  ShadowDrawCount lastFrame_;
};

}  // namespace bounce
