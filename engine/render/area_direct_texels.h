// The static area lights' direct light on the lightmap's texels, computed once when a bake is
// attached, so that a lightmapped pixel reads it bilinearly as it reads the lightmap instead of
// evaluating every static area light (shaders/area_light.glsl): the baked world's direct light
// costs what its lightmap costs. Per texel t and linear-RGB channel c, the irradiance vector
// (W/m²)
//   F_c(t) = Σ_l V_l(t) · L_l,c · Φ_l(x_t, n_t),
// l over the static area lights whose visibility the bake holds (bake_folder/light_visibility.h:
// V_l(t) exactly as the shader reads one texel, its own slot, else the "every other light" slot,
// else 1), Φ_l the light's vector form factor ×π clipped to n_t's horizon
// (scene/emitter_irradiance.h), and (x_t, n_t) the surface point whose atlas UV is nearest the
// texel's centre, with its interpolated unit shading normal. A pixel of normal n reads
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

// F_c per texel for the lights [0, lightCount) of `lights` that are static and not baked-direct
// (Material::bakeDirect: already in the lightmap), as three layers of layout.width ×
// layout.height texels (rows top first): F_c(t) at c · width · height + t. `visibility` has the
// layout's size. Instances are at their Scene transforms.
std::vector<glm::vec3> areaDirectTexels(const Scene& scene, const LightmapLayout& layout,
                                        const BakedVisibility& visibility,
                                        const AreaLightSet& lights, std::size_t lightCount);

}  // namespace bounce
