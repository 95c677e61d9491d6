// Baked light (engine/render/lightmap_pass.h) and what the lit pass outputs in each mode.
//
// The lightmap holds the irradiance E (W/m², linear RGB) a static surface receives from light
// that reflected at least once (plus the direct light of baked-only lights), one texel per atlas
// texel, read bilinearly at the fragment's atlas UV (v = 0 is the top row, as stored). A
// Lambertian surface of reflectance ρ reflects it as radiance ρ/π · E (W/(sr·m²)). A static
// instance without an atlas region (too small or thin for texels) takes the same baked light from
// its irradiance probes (probes.glsl). Dynamic instances have no atlas region: with VPLs
// (vpl.glsl) they get E_vpl instead, without none.
//
// Modes (must match lightingModeIndex in engine/render/lightmap_pass.cpp):
//   full      ρ/π · (E_direct + E_indirect) + L_e
//   direct    ρ/π · E_direct + L_e                (real-time direct light only)
//   indirect  ρ/π · E_indirect                    (compare with bounce-trace --indirect-only)
//   lightmap  E_baked / π                         (the radiance of a white, ρ = 1, surface;
//                                                  the probes' E on probe-lit instances)
//   charts    chart colour × a checker of lightmap texels (probe-lit static instances magenta,
//             dynamic instances grey)
//   vpl       ρ/π · E_vpl on every surface        (the VPLs instead of the lightmap)
//   vpl-clamp (lum(E_vpl), lum(E_removed), 0) / π: what the VPLs give and what their clamp
//             removed, for a white surface (luminance; the clamp report sums these)
//   error     each texel's estimated relative error as a false colour (bake_folder/texel_error.h,
//             computed on the CPU and bound where the chart colours are; nearest texel)
//   validity  each texel sampled, filled from its neighbours or padding (the same way; the
//             renderer's mode index is LIGHTING_ERROR's, only the bound colours differ)
//   texel-density, cascades  false colours drawn by forward.frag (view_modes.glsl)
//   cost      shaded as full (direct without a bake), written as the counts of lights, VPLs
//             and shadow-map taps the fragment evaluated (cost.glsl; forward.frag)
// E_indirect = E_baked on static surfaces (lightmap or probes), E_vpl on dynamic ones
// (uVplReceiver). LIGHTING_* and LUMINANCE_WEIGHTS come from the C++
// (engine/render/shader_constants.h).

uniform int uLightingMode;
uniform bool uHasLightmap;           // this draw: a static instance with an atlas region
uniform sampler2D uLightmap;         // E, W/m², RGB32F, bilinear, clamped at the borders
uniform sampler2D uLightmapCharts;   // chart colour per texel, nearest (black: uncovered); in
                                     // the error mode the error's false colour per texel
uniform vec2 uLightmapSize;          // atlas width, height in texels
uniform bool uVplReceiver;           // this draw: a dynamic instance lit by the VPLs

// Whether the mode needs the live direct light at all.
bool modeUsesDirectLight() {
  return uLightingMode == LIGHTING_FULL || uLightingMode == LIGHTING_DIRECT ||
         uLightingMode == LIGHTING_COST;
}

// Whether this draw evaluates the VPLs (vpl.glsl).
bool modeUsesVpls() {
  if (uLightingMode == LIGHTING_VPL || uLightingMode == LIGHTING_VPL_CLAMP) return true;
  return uVplReceiver && (uLightingMode == LIGHTING_FULL || uLightingMode == LIGHTING_INDIRECT ||
                          uLightingMode == LIGHTING_COST);
}

// E_baked (W/m²): the lightmap's, or `probeIrradiance` (probes.glsl) on a probe-lit instance.
vec3 bakedIrradiance(vec2 atlasUv, vec3 probeIrradiance) {
  if (uHasLightmap) return texture(uLightmap, atlasUv).rgb;
  return uHasProbes ? probeIrradiance : vec3(0.0);
}

const vec3 PROBE_LIT_COLOUR = vec3(0.8, 0.2, 0.8);

vec3 chartView(vec2 atlasUv) {
  if (!uHasLightmap) return uHasProbes ? PROBE_LIT_COLOUR : vec3(0.18);
  ivec2 texel = ivec2(floor(atlasUv * uLightmapSize));
  float checker = ((texel.x + texel.y) & 1) == 0 ? 1.0 : 0.55;
  return texture(uLightmapCharts, atlasUv).rgb * checker;
}

// E_indirect (W/m²): the lightmap's or the probes', or the VPLs' on a dynamic instance.
vec3 indirectIrradiance(vec2 atlasUv, vec3 vplIrradiance, vec3 probeIrradiance) {
  return uVplReceiver ? vplIrradiance : bakedIrradiance(atlasUv, probeIrradiance);
}

// Rec. 709 luminance: engine/image/luminance.h's weights.
float luminance(vec3 c) {
  return dot(c, LUMINANCE_WEIGHTS);
}

// Outgoing radiance for the current mode. `directIrradiance` is the live direct E (W/m²);
// `vplIrradiance` the VPLs' clamped E and `vplRemoved` what the clamp removed (W/m²; zero
// unless modeUsesVpls()); `probeIrradiance` the probes' E (W/m²; zero unless uHasProbes).
vec3 shadeForMode(vec3 albedo, vec3 directIrradiance, vec3 emission, vec2 atlasUv,
                  vec3 vplIrradiance, vec3 vplRemoved, vec3 probeIrradiance) {
  if (uLightingMode == LIGHTING_DIRECT) return albedo / PI * directIrradiance + emission;
  if (uLightingMode == LIGHTING_INDIRECT)
    return albedo / PI * indirectIrradiance(atlasUv, vplIrradiance, probeIrradiance);
  if (uLightingMode == LIGHTING_LIGHTMAP) return bakedIrradiance(atlasUv, probeIrradiance) / PI;
  if (uLightingMode == LIGHTING_CHARTS) return chartView(atlasUv);
  if (uLightingMode == LIGHTING_ERROR)
    return uHasLightmap ? texture(uLightmapCharts, atlasUv).rgb : vec3(0.18);
  if (uLightingMode == LIGHTING_VPL) return albedo / PI * vplIrradiance;
  if (uLightingMode == LIGHTING_VPL_CLAMP)
    return vec3(luminance(vplIrradiance), luminance(vplRemoved), 0.0) / PI;
  return albedo / PI *
             (directIrradiance + indirectIrradiance(atlasUv, vplIrradiance, probeIrradiance)) +
         emission;
}
