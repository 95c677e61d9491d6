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
