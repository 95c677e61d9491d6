// Spot-light shadows: a perspective map along the spot's axis storing distance/far
// (engine/render/spot_shadow_maps.h). Needs shadow_common.glsl.

uniform sampler2DShadow uSpotShadowMap[MAX_SPOT_SHADOWS];
uniform mat4 uSpotShadowMatrix[MAX_SPOT_SHADOWS];  // world → the map's clip space
// x: texel edge per metre of distance, y: far (m), z: filter radius (texels), w: resolution
uniform vec4 uSpotShadowParams[MAX_SPOT_SHADOWS];

float spotShadowTaps(sampler2DShadow map, vec3 q, float radius, float resolution) {
  gCostShadowTaps += uShadowFilter == 0 ? 1 : 16;
  if (uShadowFilter == 0) return texture(map, q);
  mat2 rotation = shadowKernelRotation();
  float lit = 0.0;
  for (int k = 0; k < 16; ++k)
    lit += texture(map, vec3(q.xy + rotation * POISSON16[k] * (radius / resolution), q.z));
  return lit / 16.0;
}

// Fraction of the spot's map that sees p (1 = lit), for spot `slot` at `lightPosition`.
float spotShadow(int slot, vec3 p, vec3 ng, vec3 lightPosition) {
  vec4 params = uSpotShadowParams[slot];
  vec3 toLight = lightPosition - p;
  float distance = length(toLight);
  vec2 bias = shadowBias(params.x * distance, ng, toLight / distance, params.z);
  vec3 shifted = p + ng * bias.x;
  vec4 clip = uSpotShadowMatrix[slot] * vec4(shifted, 1.0);
  if (clip.w <= 0.0) return 1.0;  // behind the spot: its cone gives no light there anyway
  vec3 q = vec3(clip.xy / clip.w * 0.5 + 0.5, (length(lightPosition - shifted) - bias.y) / params.y);
  // Constant indices only (GLSL 3.30 sampler arrays).
  if (slot == 0) return spotShadowTaps(uSpotShadowMap[0], q, params.z, params.w);
  if (slot == 1) return spotShadowTaps(uSpotShadowMap[1], q, params.z, params.w);
  if (slot == 2) return spotShadowTaps(uSpotShadowMap[2], q, params.z, params.w);
  return spotShadowTaps(uSpotShadowMap[3], q, params.z, params.w);
}
