// Baked light (engine/render/lightmap_pass.h) and what the lit pass outputs in each mode.
//
// The lightmap holds the irradiance E (W/m², linear RGB) a static surface receives from light
// that reflected at least once (plus the direct light of baked-only lights), one texel per atlas
// texel, read bilinearly at the fragment's atlas UV (v = 0 is the top row, as stored). A
// Lambertian surface of reflectance ρ reflects it as radiance ρ/π · E (W/(sr·m²)). Dynamic
// instances have no atlas region and get none.
//
// Modes (must match lightingModeIndex in engine/render/lightmap_pass.cpp):
//   full      ρ/π · (E_direct + E_baked) + L_e
//   direct    ρ/π · E_direct + L_e                (real-time direct light only)
//   indirect  ρ/π · E_baked                       (compare with bounce-trace --indirect-only)
//   lightmap  E_baked / π                         (the radiance of a white, ρ = 1, surface)
//   charts    chart colour × a checker of lightmap texels (dynamic instances grey)
const int LIGHTING_FULL = 0;
const int LIGHTING_DIRECT = 1;
const int LIGHTING_INDIRECT = 2;
const int LIGHTING_LIGHTMAP = 3;
const int LIGHTING_CHARTS = 4;

uniform int uLightingMode;
uniform bool uHasLightmap;           // this draw: a static instance with an atlas region
uniform sampler2D uLightmap;         // E, W/m², RGB32F, bilinear, clamped at the borders
uniform sampler2D uLightmapCharts;   // chart colour per texel, nearest (black: uncovered)
uniform vec2 uLightmapSize;          // atlas width, height in texels

// Whether the mode needs the live direct light at all.
bool modeUsesDirectLight() {
  return uLightingMode == LIGHTING_FULL || uLightingMode == LIGHTING_DIRECT;
}

vec3 bakedIrradiance(vec2 atlasUv) {
  return uHasLightmap ? texture(uLightmap, atlasUv).rgb : vec3(0.0);
}

vec3 chartView(vec2 atlasUv) {
  if (!uHasLightmap) return vec3(0.18);
  ivec2 texel = ivec2(floor(atlasUv * uLightmapSize));
  float checker = ((texel.x + texel.y) & 1) == 0 ? 1.0 : 0.55;
  return texture(uLightmapCharts, atlasUv).rgb * checker;
}

// Outgoing radiance for the current mode. `directIrradiance` is the live direct E (W/m²).
vec3 shadeForMode(vec3 albedo, vec3 directIrradiance, vec3 emission, vec2 atlasUv) {
  if (uLightingMode == LIGHTING_DIRECT) return albedo / PI * directIrradiance + emission;
  if (uLightingMode == LIGHTING_INDIRECT) return albedo / PI * bakedIrradiance(atlasUv);
  if (uLightingMode == LIGHTING_LIGHTMAP) return bakedIrradiance(atlasUv) / PI;
  if (uLightingMode == LIGHTING_CHARTS) return chartView(atlasUv);
  return albedo / PI * (directIrradiance + bakedIrradiance(atlasUv)) + emission;
}
