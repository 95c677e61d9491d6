// The constants the renderer's GLSL shares with its C++, handed to every program at load as
// `#define`s (gl/shader_source.h), so that no shader file holds a copy that could drift: the
// lit pass's lighting modes, the light kinds of the light table, the luminance weights, π, the
// shadow arrays' sizes and the reference view's scale. shaders/ never declares these names
// (ShaderConstants.NoShaderFileDeclaresThem checks every file).
#pragma once

#include "gl/shader_source.h"

namespace bounce {

// What forward.frag draws (uLightingMode; shaders/lightmap.glsl says what each computes). The
// render modes map onto these (Error and Validity share one: only their bound colours differ).
enum class ShaderLighting : int {
  Full = 0,
  Direct = 1,
  Indirect = 2,
  Lightmap = 3,
  Charts = 4,
  Vpl = 5,
  VplClamp = 6,
  Error = 7,
  TexelDensity = 8,
  Cascades = 9,
  Cost = 10,  // the full frame's per-pixel work counted (shaders/cost.glsl)
};

// The baked-visibility table's light code for a slot that stands for every light the texel does
// not name (bake_folder/light_visibility.h's kOtherLights); an empty slot is −1.
inline constexpr float kVisibilityOtherLightsCode = -2.0f;

// The defines, in a fixed order: LIGHTING_*, LIGHT_POINT/SPOT/DIRECTIONAL (scene.h's LightType),
// LUMINANCE_WEIGHTS (image/luminance.h), PI, MAX_SPOT_SHADOWS, MAX_POINT_SHADOWS, MAX_CASCADES,
// MAX_AREA_SHADOWS, AREA_SHADOW_SAMPLES, MAX_VPL_SHADOW_CUBES, VISIBILITY_OTHER_LIGHTS,
// CASCADE_COLOURS, TEXEL_CHECKER_DARK, NO_LIGHTMAP_GREY, DIFFERENCE_FULL_SCALE, DIFFERENCE_FLOOR.
const gl::ShaderDefines& shaderConstants();

}  // namespace bounce
