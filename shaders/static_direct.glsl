// The static lights' direct light where it was computed once, when the bake was attached,
// instead of per pixel (area_light.glsl and lights.glsl skip those lights): per lightmap texel
// for lightmapped surfaces (render/static_direct_texels.h) and per triangle corner for the
// probe-lit instances (render/static_direct_corners.h), both as irradiance vectors F_r, F_g, F_b (W/m²), so that a
// pixel of unit normal n gets E_c = max(n·F_c, 0) and the light follows the normal where it
// turns within a texel or a triangle.

// uCornerVisibilityFirst:
#include "baked_visibility.glsl"

// Texels: 3 layers (F_r, F_g, F_b), RGB32F, bilinear like the lightmap; whether this draw reads
// them (a lightmapped instance, the bake has the lights' visibility).
uniform sampler2DArray uStaticDirect;
uniform bool uStaticDirectFromTexels;
// Corners: 3 texels per corner of the probe-lit instances' visibility (corner k of the draw's
// triangle t at uCornerVisibilityFirst + 3t + k, as baked_visibility.glsl numbers them); w = 1
// where the triangle reads them, 0 on a triangle too large for it (evaluated per pixel).
uniform samplerBuffer uCornerStaticDirect;
uniform bool uHasCornerStaticDirect;

vec3 irradianceFromVectors(vec3 fr, vec3 fg, vec3 fb, vec3 n) {
  return max(vec3(dot(n, fr), dot(n, fg), dot(n, fb)), vec3(0.0));
}

// At atlas UV `atlasUv` (the lightmap's clamped lookup).
vec3 staticDirectFromTexels(vec2 atlasUv, vec3 n) {
  return irradianceFromVectors(texture(uStaticDirect, vec3(atlasUv, 0.0)).xyz,
                               texture(uStaticDirect, vec3(atlasUv, 1.0)).xyz,
                               texture(uStaticDirect, vec3(atlasUv, 2.0)).xyz, n);
}

// On triangle `triangle` of the draw at barycentric weights `weights` (clamped and renormalised,
// as the corner visibility is read).
vec3 staticDirectFromCorners(int triangle, vec3 weights, vec3 n) {
  vec3 b = max(weights, vec3(0.0));
  b /= max(b.x + b.y + b.z, 1e-6);
  vec3 f[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  for (int k = 0; k < 3; ++k) {
    int c = 3 * (uCornerVisibilityFirst + 3 * triangle + k);
    for (int ch = 0; ch < 3; ++ch) f[ch] += b[k] * texelFetch(uCornerStaticDirect, c + ch).xyz;
  }
  return irradianceFromVectors(f[0], f[1], f[2], n);
}

// Whether this fragment reads the static area lights from texels or corners.
bool staticDirectPrecomputed(int triangle) {
  if (uHasCornerStaticDirect)
    return texelFetch(uCornerStaticDirect, 3 * (uCornerVisibilityFirst + 3 * triangle)).w > 0.5;
  return uStaticDirectFromTexels;
}

vec3 staticDirect(vec2 atlasUv, int triangle, vec3 weights, vec3 n) {
  return uHasCornerStaticDirect ? staticDirectFromCorners(triangle, weights, n)
                              : staticDirectFromTexels(atlasUv, n);
}
