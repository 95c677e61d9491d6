// Which area lights get the renderer's shadow cubes (area_shadow_maps.h): the ones that bring
// the most light where a cube is read, not the most powerful in the scene. GL-free.
//
// A cube is read (shaders/area_light.glsl) by dynamic receivers, by every surface that has no
// baked visibility for the light, and, for the dynamic casters' shadows, by static surfaces
// next to dynamic instances. So a light's contribution C_l (W/m², brightest channel) is the
// largest of
//   - at each dynamic instance's world box: the most irradiance a surface anywhere on the box
//     could get from the light, unshadowed (max over the box's corners, centre and the point
//     nearest the light's centre). A caster's shadow on what it stands on removes about what
//     reaches the caster, so this ranks both the dynamic receivers and the dynamic shadows;
//   - over the visible surfaces, for a light whose visibility static surfaces do not have
//     baked: the mean of that irradiance over points standing for them (the renderer takes a
//     3³ grid over the visible part of each static, non-emitting instance's box).
// The irradiance a surface with normal n at p gets from a polygon of radiance L is L·n·Φ(p),
// Φ Lambert's vector irradiance (per unit radiance: ½ Σ_edges θ_e·Γ_e); its largest value over n
// is L·|Φ|, never more than π·L. Lights with C_l at or above the renderer's irradiance floor
// (light_culling.h: below it a light is not shaded at all) compete for the slots, largest
// first (chooseShadowedLights, shadow_choice.h).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/shadow_choice.h"
#include "scene/area_lights.h"
#include "scene/box.h"

namespace bounce {

// Slots of the shader's uniform arrays (MAX_AREA_SHADOWS in shaders/shadow_area.glsl: 32 light
// points each, 96 vec3 per 3 slots of the fragment uniforms).
constexpr int kMaxAreaShadows = 6;

// How many cubes fit at once: six layers each in a depth array of at most `maxArrayLayers`
// (GL_MAX_ARRAY_TEXTURE_LAYERS, ≥ 256 in GL 3.3), at most kMaxAreaShadows.
constexpr int areaShadowSlotCapacity(int maxArrayLayers) {
  return maxArrayLayers / 6 < kMaxAreaShadows ? maxArrayLayers / 6 : kMaxAreaShadows;
}

// Where the cubes are read (shadow_choice.h), and which lights static surfaces read them for.
struct AreaShadowReceivers : ShadowReceivers {
  // Lights [0, n) have baked visibility on every static surface: the view points do not rank
  // them (static surfaces never read their cubes).
  std::size_t bakedVisibilityLights = 0;
  // With a bake, lights whose direct light is baked (AreaLight::bakeDirect) are not drawn at all.
  bool bakedDirectSkipped = false;
};

// The most irradiance (W/m², brightest channel) a surface at `p` can get from light `light` of
// `set`, unshadowed: |Σ_t L_t·Φ_t(p)| over its triangles, capped at π·L. Zero behind a
// single-sided light.
float largestIrradiance(const AreaLightSet& set, std::size_t light, glm::vec3 p);

// C_l of every light of `set` (W/m², see above; 0 for a light under `floor` everywhere the
// cubes are read, shadowContribution), in the set's order.
std::vector<float> areaLightContributions(const AreaLightSet& set,
                                          const AreaShadowReceivers& receivers, float floor = 0.0f);

// One sentence for the renderer's log: how many lights have a cube of how many slots, and what
// the lights left without one bring (count, summed and largest contribution, share).
std::string describeAreaShadowChoice(const ShadowChoice& choice, int slots);

}  // namespace bounce
