// Area-light shadows: for each of the most powerful area lights (scene/area_lights.h), a depth
// cube map from the light's centre storing distance/far (the point lights' depth pass, less the
// light's own instance), read by shaders/shadow_area.glsl as plain distances (no
// comparison) for percentage-closer soft shadows. The lights' unshadowed irradiance stays the
// exact polygon integral of shaders/area_light.glsl; the map only scales it by the visible
// fraction of the light.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gl/depth_sampler.h"
#include "gl/depth_texture.h"
#include "gl/shader.h"
#include "render/gpu_scene.h"
#include "render/shadow_map_geometry.h"

namespace bounce {

// Must match MAX_AREA_SHADOWS and AREA_SHADOW_SAMPLES in shaders/shadow_area.glsl.
constexpr int kMaxAreaShadows = 3;
constexpr int kAreaShadowSamples = 32;

class AreaShadowMaps {
 public:
  AreaShadowMaps(const ShadowSettings& settings) : settings_(settings) {}

  // Groups the scene's emitters into lights and gives the most powerful kMaxAreaShadows a cube
  // (a warning names how many stay unshadowed).
  void add(const GpuScene& scene, std::vector<std::string>& warnings);
  // Renders the faces that may reach the view (the others are cleared to the far plane: soft-
  // shadow taps may stray into them from a visible receiver). Re-reads the lights' geometry first
  // when an emitting instance moved (the emitter table changed).
  ShadowDrawCount render(const GpuScene& scene, const ViewVolume& view, gl::Program& depthProgram,
                         gl::DepthTarget& target);
  void bind(gl::Program& forward) const;
  // With baked visibility the static surfaces already hold the static occluders' shadows; what
  // they still need from the maps is the dynamic instances' (V = V_baked · V_dynamic): on, each
  // cube gets a second one of only the dynamic instances (texture units kAreaDynamicShadow0..).
  // Returns false, changing nothing, when the driver lacks those units.
  bool setDynamicCasterCubes(bool enabled);
  // Off, the all-caster cubes are not drawn (nothing reads them: every surface has baked
  // visibility and no dynamic instance exists); the lit pass is told there are none.
  void setAllCasterCubesNeeded(bool needed) { allCastersNeeded_ = needed; }

 private:
  struct Cube {
    std::size_t index = 0;  // into GpuScene::areaLights().lights
    AreaLight light;
    glm::vec3 origin{0.0f};         // the map's centre: the light's area-weighted centre
    std::vector<glm::vec3> points;  // kAreaShadowSamples points on the light, world metres
    glm::ivec2 rows{0};             // the light's rows [first, end) of the emitter table
    std::optional<gl::DepthCubeMap> texture;
    std::optional<gl::DepthCubeMap> dynamicTexture;  // the dynamic instances only
    int resolution = 0;
    float far = 1.0f;
  };
  void place(const GpuScene& scene);

  ShadowSettings settings_;
  std::vector<Cube> cubes_;
  std::optional<gl::DepthValueSampler> sampler_;
  int emitterVersion_ = -1;
  bool dynamicCubes_ = false;
  bool allCastersNeeded_ = true;
};

}  // namespace bounce
