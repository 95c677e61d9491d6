// The one light table (engine/render/light_table.h): an RGBA32F buffer texture with every
// punctual light, then the VPLs, then the VPL cuts; no light kind has a fixed cap. Indices and
// counts are stored as floats (exact below 2^24, the table's limit). PI and LIGHT_* come from the
// C++ (engine/render/shader_constants.h).

uniform samplerBuffer uLightTable;
uniform int uPunctualCount;   // punctual lights at texels 0 .. 4·count − 1
uniform int uVplLightsFirst;  // first texel of the VPL lights (3 each)
uniform int uVplCutsFirst;    // first texel of the VPL cuts (1 each)

struct PunctualLight {
  int type;          // LIGHT_*
  vec3 position;     // metres (point, spot)
  vec3 direction;    // unit, the way light travels (spot, directional)
  int shadowSlot;    // its map among its kind's, −1: unshadowed
  vec3 power;        // intensity W/sr (point, spot) or irradiance W/m² (directional)
  int bakedIndex;    // its index in the bake's visibility (baked_visibility.glsl), −1: none
  vec2 cosCone;      // spot: cos(inner), cos(outer)
  // Its direct light on static surfaces is in the texels and corners (static_direct.glsl):
  // render/punctual_lights.h, PunctualLights::precomputed.
  bool precomputed;
};

PunctualLight punctualLight(int i) {
  vec4 t0 = texelFetch(uLightTable, 4 * i);
  vec4 t1 = texelFetch(uLightTable, 4 * i + 1);
  vec4 t2 = texelFetch(uLightTable, 4 * i + 2);
  vec4 t3 = texelFetch(uLightTable, 4 * i + 3);
  return PunctualLight(int(t0.w), t0.xyz, t1.xyz, int(t1.w), t2.rgb, int(t2.w), t3.xy,
                       t3.z > 0.5);
}

// A range (first, count) stored in the cut section at `texel` (relative to the section).
uvec2 vplCutRange(int texel) {
  vec2 range = texelFetch(uLightTable, uVplCutsFirst + texel).xy;
  return uvec2(range);
}

// Texel k (0: position + group, 1: normal, 2: flux) of VPL light i.
vec4 vplTexel(int i, int k) {
  return texelFetch(uLightTable, uVplLightsFirst + 3 * i + k);
}
