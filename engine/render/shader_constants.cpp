#include "render/shader_constants.h"

#include <cstdio>
#include <numbers>
#include <string>

#include "image/luminance.h"
#include "render/area_shadow_budget.h"
#include "render/area_shadow_maps.h"
#include "render/cascades.h"
#include "render/reference_view.h"
#include "render/texture_units.h"
#include "render/view_mode_colours.h"
#include "render/vpl_shadow_maps.h"
#include "render/vpl_vertex_light.h"
#include "scene/scene.h"

namespace bounce {
namespace {

// GLSL float literals that read back as the same float (9 significant digits).
std::string glslFloat(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(static_cast<float>(v)));
  std::string s = text;
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string glslInt(int v) {
  return std::to_string(v);
}

std::string glslVec3(glm::vec3 v) {
  return "vec3(" + glslFloat(v.x) + ", " + glslFloat(v.y) + ", " + glslFloat(v.z) + ")";
}

// vec3[kMaxCascades](...): each cascade's false colour (view_mode_colours.h).
std::string cascadeColours() {
  std::string list;
  for (int i = 0; i < kMaxCascades; ++i) list += (i ? ", " : "") + glslVec3(cascadeColour(i));
  return "vec3[" + glslInt(kMaxCascades) + "](" + list + ")";
}

gl::ShaderDefines makeConstants() {
  const auto lighting = [](ShaderLighting l) { return glslInt(static_cast<int>(l)); };
  const auto light = [](LightType t) { return glslInt(static_cast<int>(t)); };
  return {
      {"LIGHTING_FULL", lighting(ShaderLighting::Full)},
      {"LIGHTING_DIRECT", lighting(ShaderLighting::Direct)},
      {"LIGHTING_INDIRECT", lighting(ShaderLighting::Indirect)},
      {"LIGHTING_LIGHTMAP", lighting(ShaderLighting::Lightmap)},
      {"LIGHTING_CHARTS", lighting(ShaderLighting::Charts)},
      {"LIGHTING_VPL", lighting(ShaderLighting::Vpl)},
      {"LIGHTING_VPL_CLAMP", lighting(ShaderLighting::VplClamp)},
      {"LIGHTING_ERROR", lighting(ShaderLighting::Error)},
      {"LIGHTING_TEXEL_DENSITY", lighting(ShaderLighting::TexelDensity)},
      {"LIGHTING_CASCADES", lighting(ShaderLighting::Cascades)},
      {"LIGHTING_COST", lighting(ShaderLighting::Cost)},
      {"LIGHT_POINT", light(LightType::Point)},
      {"LIGHT_SPOT", light(LightType::Spot)},
      {"LIGHT_DIRECTIONAL", light(LightType::Directional)},
      {"LUMINANCE_WEIGHTS", "vec3(" + glslFloat(kLuminanceR) + ", " + glslFloat(kLuminanceG) +
                                ", " + glslFloat(kLuminanceB) + ")"},
      {"PI", glslFloat(std::numbers::pi)},
      {"MAX_SPOT_SHADOWS", glslInt(kMaxSpotShadows)},
      {"MAX_POINT_SHADOWS", glslInt(kMaxPointShadows)},
      {"MAX_CASCADES", glslInt(kMaxCascades)},
      {"MAX_AREA_SHADOWS", glslInt(kMaxAreaShadows)},
      {"MAX_DYNAMIC_CASTERS", glslInt(static_cast<int>(kMaxDynamicCasters))},
      {"AREA_SHADOW_SAMPLES", glslInt(kAreaShadowSamples)},
      {"MAX_VPL_SHADOW_CUBES", glslInt(kMaxVplShadowCubes)},
      {"VPL_VERTEX_LIGHT_WIDTH", glslInt(kVplVertexLightWidth)},
      {"VPL_MAX_EDGE_OVER_DISTANCE", glslFloat(kVplMaxEdgeOverDistance)},
      // The visibility table's code for "every light the texel does not name" (lightmap_pass.cpp).
      {"VISIBILITY_OTHER_LIGHTS", glslFloat(kVisibilityOtherLightsCode)},
      {"CASCADE_COLOURS", cascadeColours()},
      {"TEXEL_CHECKER_DARK", glslFloat(kTexelCheckerDark)},
      {"NO_LIGHTMAP_GREY", glslFloat(kNoLightmapGrey)},
      {"DIFFERENCE_FULL_SCALE", glslFloat(kDifferenceFullScale)},
      {"DIFFERENCE_FLOOR", glslFloat(kDifferenceFloor)},
  };
}

}  // namespace

const gl::ShaderDefines& shaderConstants() {
  static const gl::ShaderDefines constants = makeConstants();
  return constants;
}

}  // namespace bounce
