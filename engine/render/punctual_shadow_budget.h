// Which point, spot and directional lights get the renderer's maps (kMaxSpotShadows spot
// maps, kMaxPointShadows point cubes, one set of directional cascades: texture_units.h) when a
// kind has more lights than maps: per kind, the ones that bring the most light where the maps
// are read, re-chosen every frame as the area cubes are (shadow_choice.h). GL-free.
//
// A punctual light's map is read everywhere it shines: by dynamic receivers, by surfaces
// without baked visibility, and by static surfaces with it for the dynamic casters' shadows
// (shaders/lights.glsl takes V = min(V_map, V_baked)). So its contribution C_l (W/m², brightest
// channel of the power it is drawn with) is the largest of
//   - at each dynamic instance's world box: the most irradiance a surface anywhere on the box
//     could get from it, unshadowed (max over the box's corners, centre and the point nearest
//     the light);
//   - the mean of that irradiance over the points standing for the visible static surfaces,
//     each weighted by the screen its surface takes (shadow_receivers.h).
// The most irradiance a surface at p can get is I·f(θ)/d² (point: f = 1; spot: f its angular
// falloff, scene/light_falloff.h), d the distance to the light, and E⊥ for a directional light.
// A light drawn with no power (its direct light baked) brings nothing and gets no map. A spot or
// point light whose visibility the bake holds for every static surface is ranked by the dynamic
// instances alone (shadow_pass.h says which).
#pragma once

#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/shadow_choice.h"
#include "scene/scene.h"

namespace bounce {

// W/m², brightest channel: the most irradiance a surface at `p` gets from `light` drawn with
// `power` (W/sr for point and spot, W/m² at normal incidence for directional), unshadowed.
float largestPunctualIrradiance(const Light& light, glm::vec3 power, glm::vec3 p);

// C_l of every light (W/m², see above; 0 for a light under `floor` everywhere the maps are
// read, shadowContribution); power[i] is light i's drawn power. A light with
// bakedOnStatics[i] != 0 has its visibility baked on every static surface: the view points do not
// rank it, only the dynamic instances in its reach (the dynamic receivers, and the dynamic
// casters' shadows on static surfaces), so with none it brings 0 and gets no map.
std::vector<float> punctualLightContributions(std::span<const Light> lights,
                                              std::span<const glm::vec3> power,
                                              const ShadowReceivers& receivers, float floor = 0.0f,
                                              std::span<const uint8_t> bakedOnStatics = {});

// How many maps each kind has.
struct PunctualShadowSlots {
  int spot = 0, point = 0, directional = 0;
  int of(LightType type) const;
};

// Each light's map slot among its kind's (−1: none) for this frame: per kind, the lights
// chooseShadowedLights picks over `floor` (W/m²) from `contributions`, `previous` holding last
// frame's slots (a light keeps its slot while it is chosen; a newly chosen light takes the
// lowest free one; a map changes hands only when another light is chosen for it, so a light
// left unchosen keeps the map no other light took).
std::vector<int> assignPunctualShadowSlots(std::span<const Light> lights,
                                           std::span<const float> contributions,
                                           const PunctualShadowSlots& slots, float floor,
                                           std::span<const int> previous);

// One sentence for the renderer's log: which lights have a map (by name) and which have none.
std::string describePunctualShadowMaps(std::span<const Light> lights, std::span<const int> slots);

}  // namespace bounce
