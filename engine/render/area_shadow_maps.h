// Area-light shadows: for each area light (scene/area_lights.h) that brings the most light where
// the cubes are read (area_shadow_budget.h, re-chosen every frame), a depth cube from the
// light's centre storing distance/far (the point lights' depth pass, less the light's own
// instance; six layers of one depth array shared by every slot, shaders/cube_face.glsl), read by
// shaders/shadow_area.glsl as plain distances (no comparison) for percentage-closer soft
// shadows. The lights' unshadowed irradiance stays the exact polygon integral of
// shaders/area_light.glsl; the map only scales it by the visible fraction of the light.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gl/depth_sampler.h"
#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/area_shadow_budget.h"
#include "render/shadow_map_geometry.h"

namespace bounce {

class GpuScene;

// Must match AREA_SHADOW_SAMPLES in shaders/shadow_area.glsl.
constexpr int kAreaShadowSamples = 32;

// Dynamic instances whose bounding spheres the lit pass tests before reading the dynamic cubes
// (shaders/shadow_area.glsl, dynamicCasterBetween); with more, every pixel reads them.
inline constexpr std::size_t kMaxDynamicCasters = 16;

class AreaShadowMaps {
 public:
  AreaShadowMaps(const ShadowSettings& settings) : settings_(settings) {}

  // Readies the cubes of `scene`'s area lights (which lights get one is chosen per frame).
  void add(const GpuScene& scene);
  // Chooses the lights for this view and the dynamic instances where they stand
  // (chooseShadowedLights over `floor`, W/m², the renderer's irradiance floor; a light
  // keeps its slot while chosen), then renders the faces that may reach the view and are not
  // already up to date (the others are cleared to the far plane: soft-shadow taps may stray
  // into them from a visible receiver). A face is redrawn when its slot got another light, an
  // instance moved (a caster, or the scene's bounds that set the map's reach) or an emitting
  // instance moved (the lights are re-read), or when it comes into view after being cleared.
  ShadowDrawCount render(const GpuScene& scene, const ViewVolume& view, float floor,
                         gl::Program& depthProgram, gl::DepthTarget& target);
  // Also the dynamic instances' bounding spheres (uDynamicCasters), with which a pixel skips
  // the dynamic cube where no dynamic instance can stand between it and the light.
  void bind(gl::Program& forward) const;
  // With baked visibility the static surfaces already hold the static occluders' shadows; what
  // they still need from the maps is the dynamic instances' (V = V_baked · V_dynamic): on, each
  // cube gets a second one of only the dynamic instances (a second array, texture unit
  // kAreaDynamicShadow0). Returns false, changing nothing, when the driver lacks that unit.
  bool setDynamicCasterCubes(bool enabled);
  // Off, the all-caster cubes are not drawn (nothing reads them: every surface has baked
  // visibility and no dynamic instance exists); the lit pass is told there are none.
  void setAllCasterCubesNeeded(bool needed) { allCastersNeeded_ = needed; }
  // Lights [0, n) have baked visibility on every static surface (LightmapPass): only dynamic
  // instances rank them.
  void setBakedVisibilityLights(std::size_t n) { bakedVisibilityLights_ = n; }
  // With a bake, lights with AreaLight::bakeDirect are not drawn: they need no cube.
  void setBakedDirectSkipped(bool skipped) { bakedDirectSkipped_ = skipped; }
  // The last frame's choice (which lights have a cube, what the rest bring) and the slots.
  const ShadowChoice& lastChoice() const { return choice_; }
  int slots() const { return slots_; }

 private:
  enum class FaceState : uint8_t { Stale, Cleared, Drawn };
  struct Cube {
    bool occupied = false;
    std::size_t index = 0;  // into GpuScene::areaLights().lights
    AreaLight light;
    glm::vec3 origin{0.0f};         // the map's centre: the light's area-weighted centre
    std::vector<glm::vec3> points;  // kAreaShadowSamples points on the light, world metres
    glm::ivec2 rows{0};             // the light's rows [first, end) of the emitter table
    float far = 1.0f;
    std::array<FaceState, 6> faces{};
  };
  // Where the cubes are read this frame (area_shadow_budget.h).
  AreaShadowReceivers receivers(const GpuScene& scene, const ViewVolume& view) const;
  // Gives the chosen lights slots: a light already holding one keeps it (its layers stay).
  void assign(const GpuScene& scene, const std::vector<uint32_t>& lights);
  void place(const GpuScene& scene, Cube& cube) const;

  ShadowSettings settings_;
  std::vector<Cube> cubes_;                       // slot i: layers 6i..6i+5
  std::optional<gl::DepthTextureArray> maps_;     // every caster
  std::optional<gl::DepthTextureArray> dynamic_;  // the dynamic instances only
  std::optional<gl::DepthValueSampler> sampler_;
  int resolution_ = 0;  // texels per face side, every slot's
  int slots_ = 0;       // most cubes at once (areaShadowSlotCapacity, at most the lights)
  ShadowChoice choice_;
  std::vector<glm::mat4> drawnModels_;  // every instance's model when the faces were drawn
  // The dynamic instances' bounding spheres (centre, radius; m) at the last render; empty with
  // more than kMaxDynamicCasters of them (the pixels then test every cube).
  std::vector<glm::vec4> dynamicCasters_;
  bool tooManyDynamicCasters_ = false;
  int emitterVersion_ = -1;
  std::size_t bakedVisibilityLights_ = 0;
  bool bakedDirectSkipped_ = false;
  bool dynamicCubes_ = false;
  bool allCastersNeeded_ = true;
};

}  // namespace bounce
