// Texture units of the lit forward pass, one table (GL 3.3 guarantees 16 in a fragment shader).
// Every sampler uniform is pointed at its own unit on every draw: two samplers of different
// types on one unit are a GL error even when neither is read.
#pragma once

namespace bounce {

struct TextureUnit {
  static constexpr int kAlbedo = 0;             // sampler2D: material base colour
  static constexpr int kEmitters = 1;           // sampler2D: area-light table (area_light.glsl)
  static constexpr int kSpotShadow0 = 2;        // sampler2DShadow × kMaxSpotShadows (2..5)
  static constexpr int kPointShadow0 = 6;       // samplerCubeShadow × kMaxPointShadows (6..7)
  static constexpr int kDirectionalShadow = 8;  // reserved: cascades (shadow_directional.glsl)
  // sampler2DArray: every area-light slot's cube, 6 layers each (area_shadow_maps.h)
  static constexpr int kAreaShadow0 = 9;
  static constexpr int kProbes = 10;  // samplerBuffer: irradiance probes (probes.glsl)
  // samplerBuffer: the probe-lit instances' baked visibility per corner (baked_visibility.glsl)
  static constexpr int kCornerVisibility = 11;
  static constexpr int kLightmap = 12;        // sampler2D: baked irradiance (lightmap.glsl)
  static constexpr int kLightmapCharts = 13;  // sampler2D: chart colours (lightmap.glsl)
  static constexpr int kLightTable = 14;      // samplerBuffer: every light (render/light_table.h)
  // sampler2DArrayShadow: the VPL groups' shadow cubes (vpl_shadows.glsl). Beyond the 16 units
  // GL 3.3 guarantees: VplPass turns VPL shadows off, with a warning, on a driver without it.
  static constexpr int kVplShadow =
      15;  // sampler2DArrayShadow: VPL shadow cubes (vpl_shadows.glsl)
  // sampler2D: the static area lights' baked visibility (baked_visibility.glsl). Beyond GL 3.3's
  // 16: on a driver without it the sampler shares kLightmap's unit (both sampler2D) and
  // LightmapPass leaves the visibility out (area lights fall back to their shadow maps).
  static constexpr int kBakedVisibility = 16;
  // sampler2DArray: the area-light cubes of the dynamic instances alone, for static receivers
  // whose static shadows are baked (area_shadow_maps.h).
  static constexpr int kAreaDynamicShadow0 = 17;
  // sampler2DArray: the static lights' irradiance vectors per lightmap texel (static_direct.glsl,
  // static_direct_texels.h). On a driver without it those lights are evaluated per pixel, as
  // without a bake.
  static constexpr int kStaticDirect = 18;
  // samplerBuffer: the same per triangle corner of the probe-lit instances (probes.glsl,
  // static_direct_corners.h); without it those instances evaluate the lights per pixel.
  static constexpr int kCornerStaticDirect = 19;
  // Read by forward.vert (GL 3.3 gives 48 units to all stages together): the VPLs' light at the
  // dynamic instances' vertices (sampler2D) and the draw's corner → vertex table (usamplerBuffer),
  // render/vpl_vertex_light.h. Without them the dynamic pixels gather the VPLs themselves.
  static constexpr int kVplVertexLight = 20;
  static constexpr int kVplCornerVertex = 21;
};

// Must match MAX_SPOT_SHADOWS / MAX_POINT_SHADOWS in shaders/shadow_spot.glsl, shadow_point.glsl.
constexpr int kMaxSpotShadows = 4;
constexpr int kMaxPointShadows = 2;

}  // namespace bounce
