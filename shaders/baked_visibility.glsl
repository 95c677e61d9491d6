// Baked visibility of the static lights (engine/bake_folder/light_visibility.h): per lightmap
// texel up to 4 (light, V) pairs, V the visible fraction of the light's unshadowed irradiance;
// lights 0 .. uBakedLightCount − 1 are the static area lights, the punctual ones follow
// (PunctualLight.bakedIndex, light_table.glsl).
// Read with the lightmap's bilinear weights at the fragment's atlas UV, each of the 4 texels
// giving its own V for the light (its slot's, else its "every other light" slot's, else 1: the
// light brought that texel nothing), so a light absent from one texel never borrows another
// light's V.
//
// Table (uBakedVisibility, RGBA32F, 2·W × H, texelFetch): texel (2x, y) holds the 4 slots'
// light indices (−1 empty, −2 every other light), texel (2x + 1, y) their V.

uniform bool uHasBake;                // a bake is attached (baked-direct lights are not drawn)
uniform bool uHasBakedVisibility;     // this draw: a static instance, the bake has visibility
uniform int uBakedLightCount;         // static area lights the bake names (the first indices)
uniform sampler2D uBakedVisibility;
// The probe-lit instances' visibility per triangle corner (bake_folder/irradiance_probes.h,
// ProbeVisibility; render/probe_pass.h): texel 2c holds corner c's slots' light indices, texel
// 2c + 1 their V, as the table above.
uniform samplerBuffer uCornerVisibility;
uniform bool uHasCornerVisibility;  // this draw: a probe-lit instance with corner visibility
uniform int uCornerVisibilityFirst;  // its first corner


struct BakedVisibilityTexels {
  vec4 lights[4];
  vec4 visible[4];
  vec4 weight;  // bilinear weights of the 4 texels
};

// The 4 texels around atlas UV `atlasUv` (texel centres at (i + ½)/size), clamped to the atlas.
BakedVisibilityTexels bakedVisibilityTexels(vec2 atlasUv, vec2 size) {
  BakedVisibilityTexels t;
  vec2 x = atlasUv * size - 0.5;
  vec2 f = x - floor(x);
  ivec2 base = ivec2(floor(x));
  ivec2 last = ivec2(size) - 1;
  for (int k = 0; k < 4; ++k) {
    ivec2 q = clamp(base + ivec2(k & 1, k >> 1), ivec2(0), last);
    t.lights[k] = texelFetch(uBakedVisibility, ivec2(2 * q.x, q.y), 0);
    t.visible[k] = texelFetch(uBakedVisibility, ivec2(2 * q.x + 1, q.y), 0);
  }
  t.weight = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  return t;
}

// The same from the 3 corners of triangle `triangle` of the draw (corner k of triangle t at
// 3t + k), weighted by the fragment's barycentric weights: V = Σ_k b_k V_k, linear over the
// triangle as the corners' V was estimated (corner_visibility_bake.h). The fourth entry is empty.
BakedVisibilityTexels cornerVisibilityTexels(int triangle, vec3 weights) {
  BakedVisibilityTexels t;
  vec3 b = max(weights, vec3(0.0));
  b /= max(b.x + b.y + b.z, 1e-6);
  for (int k = 0; k < 3; ++k) {
    int c = uCornerVisibilityFirst + 3 * triangle + k;
    t.lights[k] = texelFetch(uCornerVisibility, 2 * c);
    t.visible[k] = texelFetch(uCornerVisibility, 2 * c + 1);
  }
  t.lights[3] = vec4(-1.0);
  t.visible[3] = vec4(1.0);
  t.weight = vec4(b, 0.0);
  return t;
}

// V of static light `light` from one texel's slots: its own slot's V where the texel names it,
// else the "every other light" slot's V when `useShared` (else 1: the light brought the texel
// nothing). The shared V is exact for the others' sum, each light weighted by it, not a bound
// on one light's own V: a punctual light with a shadow map does not use it (lights.glsl).
float texelVisibility(vec4 lights, vec4 visible, float light, bool useShared) {
  float other = 1.0;
  for (int s = 0; s < 4; ++s) {
    if (lights[s] == light) return visible[s];
    if (lights[s] == VISIBILITY_OTHER_LIGHTS) other = visible[s];
  }
  return useShared ? other : 1.0;
}

float bakedVisibility(BakedVisibilityTexels t, int light, bool useShared) {
  float v = 0.0;
  for (int k = 0; k < 4; ++k)
    v += t.weight[k] * texelVisibility(t.lights[k], t.visible[k], float(light), useShared);
  return v;
}
