// The static lights' direct light on the lightmap's texels, computed once when a bake is
// attached, so that a lightmapped pixel reads it bilinearly as it reads the lightmap instead of
// evaluating every static light (shaders/area_light.glsl, lights.glsl): the baked world's direct
// light costs what its lightmap costs. Per texel t and linear-RGB channel c, the irradiance
// vector (W/m²)
//   F_c(t) = Σ_l V_l(t) · F_l,c(x_t, n_t),
// l over the static lights whose visibility the bake holds (PrecomputedLights below;
// bake_folder/light_visibility.h: V_l(t) exactly as the shader reads one texel, its own slot,
// else the "every other light" slot, else 1), F_l,c the light's unshadowed irradiance vector
// clipped to n_t's horizon (scene/emitter_irradiance.h: an area light's L·Φ, Φ its vector form
// factor ×π; a point or spot light's I·falloff/r² along the direction to it; a directional
// light's E⊥ along it), and (x_t, n_t) the surface point whose atlas UV is nearest the texel's
// centre, with its interpolated unit shading normal. A pixel of normal n reads
// E_c = max(n·F_c, 0): exact at n = n_t up to interpolation (the pixel's own E_l · bilinear(V_l)
// becomes bilinear(V_l · E_l), the same wherever E_l is linear across a texel), and it follows
// the normal where it turns within a texel (rounded edges, slats, trims) as long as the pixel's
// horizon cuts no light the texel's does not.
//
// Texels within one texel (either axis) of a triangle of a lightmapped instance are computed: the
// bilinear taps of any lookup the forward shader makes (its UV clamped into the triangle,
// forward.geom) and no further; the atlas keeps 2 texels free around every chart, so such a
// texel belongs to one chart, and to its nearest triangle there. Other texels are 0. GL-free.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/light_visibility.h"
#include "bake_folder/lightmap_layout.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace bounce {

// The static lights whose direct light on static surfaces is computed once: the area lights
// [0, areaCount) of `area` that are static and not baked-direct (Material::bakeDirect: in the
// lightmap already), whose visibility index is their own, and the punctual lights i with
// precomputed[i] (PunctualLights::precomputed), whose visibility index is the visibility's
// lightCount + i (bake_folder/light_visibility.h).
struct PrecomputedLights {
  const AreaLightSet* area = nullptr;
  std::size_t areaCount = 0;
  std::span<const Light> punctual;
  std::span<const uint8_t> precomputed;

  // Area lights [0, areaLights()) may be computed: the static ones the bake names.
  std::size_t areaLights() const;
  // Area light l is computed: within areaLights() and not baked into the lightmap itself.
  bool areaComputed(std::size_t l) const;
  // Punctual light i is computed.
  bool punctualComputed(std::size_t i) const {
    return i < precomputed.size() && precomputed[i] != 0;
  }
};

// Adds to f the irradiance vectors F_c of `lights` at x with unit normal n (clipped to its
// horizon) where the visibility record `visible` (of a visibility with `areaLightCount` area
// lights) gives them V > 0, each times its V: what a texel or a corner holds.
void addStaticDirect(const PrecomputedLights& lights, const TexelVisibility& visible,
                     uint32_t areaLightCount, glm::vec3 x, glm::vec3 n, glm::vec3 f[3]);

// F_c per texel, as three layers of layout.width × layout.height texels (rows top first): F_c(t)
// at c · width · height + t. `visibility` has the layout's size. Instances are at their Scene
// transforms.
std::vector<glm::vec3> staticDirectTexels(const Scene& scene, const LightmapLayout& layout,
                                          const BakedVisibility& visibility,
                                          const PrecomputedLights& lights);

}  // namespace bounce
