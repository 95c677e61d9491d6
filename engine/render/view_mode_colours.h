// The false colours of the renderer's inspection views texel-density and cascades, GL-free; the
// shader shaders/view_modes.glsl computes the same colours (its constants are these, handed to it
// by render/shader_constants.h; its formulas must stay equal to these). They
// are the views' output radiance in W/(sr·m²), as the chart view's are: a picture, not light.
//
// texel-density (as Unreal's lightmap density view): the lightmap texels per metre d on the
// surface against the bake's target d₀ = 1 / layout.texelSize (bake.json's texel size):
//   r = log₂(d / d₀):  ≤ −1 (texels twice the target's edge or larger) → blue (0, 0, 1),
//                       0 (the target) → green (0, 1, 0),  ≥ +1 (half its edge or smaller) → red,
//   linear in r between; × a checker of lightmap texels (1 or kTexelCheckerDark), so the texel
//   grid itself shows at its size in the world. Surfaces without a lightmap: kNoLightmapGrey.
//
// cascades: the index of the directional light's shadow cascade a fragment reads
// (shaders/shadow_directional.glsl: the first whose slice ends beyond its view depth, the last
// beyond every split), cascade 0..3 → red, green, blue, yellow; in the blend band of cascade i
// (view depth from blendStart to the split) the colours cross-fade as the visibility does,
// (1 − w)·colour_i + w·colour_{i+1}, w = (z − blendStart) / (split − blendStart). Without a
// shadowed directional light every surface is kNoLightmapGrey.
#pragma once

#include <glm/vec3.hpp>

namespace bounce {

inline constexpr float kTexelCheckerDark = 0.55f;  // the darker squares of the texel checker
inline constexpr float kNoLightmapGrey = 0.18f;    // surfaces the view says nothing about

// The density colour of d texels per metre against the target d₀ (both > 0), before the checker.
glm::vec3 texelDensityColour(float texelsPerMetre, float targetTexelsPerMetre);

// Cascade i's colour (i in 0..3; kMaxCascades).
glm::vec3 cascadeColour(int cascade);

}  // namespace bounce
