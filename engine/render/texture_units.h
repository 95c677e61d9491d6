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
  static constexpr int kAreaShadow0 = 9;        // samplerCube × 3: area-light slots 0..2 (9..11)
  static constexpr int kLightmap = 12;          // sampler2D: baked irradiance (lightmap.glsl)
  static constexpr int kLightmapCharts = 13;    // sampler2D: chart colours (lightmap.glsl)
  static constexpr int kLightTable = 14;        // samplerBuffer: every light (render/light_table.h)
  // sampler2DArrayShadow: the VPL groups' shadow cubes (vpl_shadows.glsl). Beyond the 16 units
  // GL 3.3 guarantees: VplPass turns VPL shadows off, with a warning, on a driver without it.
  static constexpr int kVplShadow =
      15;  // sampler2DArrayShadow: VPL shadow cubes (vpl_shadows.glsl)
  // sampler2D: the static area lights' baked visibility (baked_visibility.glsl). Beyond GL 3.3's
  // 16: on a driver without it the sampler shares kLightmap's unit (both sampler2D) and
  // LightmapPass leaves the visibility out (area lights fall back to their shadow maps).
  static constexpr int kBakedVisibility = 16;
  // samplerCube × 3 (17..19): the area-light cubes of the dynamic instances alone, for static
  // receivers whose static shadows are baked (area_shadow_maps.h).
  static constexpr int kAreaDynamicShadow0 = 17;
  // samplerCube: area-light slots 3..5 where the driver has the units (areaShadowUnit): their
  // all-caster cubes (20..22), then their dynamic-caster cubes (23..25).
  static constexpr int kAreaShadowMore0 = 20;
  static constexpr int kAreaDynamicShadowMore0 = 23;
};

// Area-light shadow slots: must match MAX_AREA_SHADOWS in shaders/shadow_area.glsl. Slots 0..2
// fit GL 3.3's 16 units; 3..5 need units 20..25.
constexpr int kMaxAreaShadows = 6;
constexpr int kAreaShadowsWithin16Units = 3;

// The unit of slot `slot`'s all-caster cube, or (dynamicCasters) of its dynamic-caster cube.
constexpr int areaShadowUnit(int slot, bool dynamicCasters) {
  if (slot < kAreaShadowsWithin16Units)
    return (dynamicCasters ? TextureUnit::kAreaDynamicShadow0 : TextureUnit::kAreaShadow0) + slot;
  return (dynamicCasters ? TextureUnit::kAreaDynamicShadowMore0 : TextureUnit::kAreaShadowMore0) +
         slot - kAreaShadowsWithin16Units;
}

// How many area-light slots a driver with `fragmentUnits` texture units holds: every slot's
// all-caster cube and, with `dynamicCasterCubes`, its dynamic-caster cube on a unit below it.
constexpr int areaShadowSlots(int fragmentUnits, bool dynamicCasterCubes) {
  int slots = 0;
  while (slots < kMaxAreaShadows && areaShadowUnit(slots, false) < fragmentUnits &&
         (!dynamicCasterCubes || areaShadowUnit(slots, true) < fragmentUnits))
    ++slots;
  return slots;
}

// Must match MAX_SPOT_SHADOWS / MAX_POINT_SHADOWS in shaders/shadow_spot.glsl, shadow_point.glsl.
constexpr int kMaxSpotShadows = 4;
constexpr int kMaxPointShadows = 2;

}  // namespace bounce
