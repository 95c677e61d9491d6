// Cascaded shadow maps of one directional light (engine/render/cascades.h): the visible fraction
// V of the light at a receiver, to multiply its irradiance E⊥·cosθ (lights.glsl).
//
// Cascade i (of uCascadeCount) is an orthographic depth map over its slice of the view frustum,
// stored as tile i of a 2×2 atlas (tile i at ((i & 1), (i >> 1))·½ in texture coordinates); its
// depth is linear in metres along the light over the scene's range. A fragment at view depth z
// reads the first cascade whose slice ends beyond z, and in the last share of that slice (from
// blendStart to the split) cross-fades into the next one, which also covers it, so no border
// shows a jump.
//
// Bias: the rule every shadow map shares (shadow_common.glsl's shadowBias), with w the
// cascade's texel edge in metres (an orthographic map: the same at every distance), so the
// normal offset and the depth bias shrink with the cascade's texels. Filter: the same as spot
// maps (uShadowFilter: one hardware 2×2 tap, or 16 rotated Poisson taps of R texels), R in
// texels of each cascade. Needs shadow_common.glsl.


uniform int uCascadeCount;  // 0: no directional light is shadowed
uniform sampler2DShadow uCascadeMap;
uniform mat4 uCascadeWorldToClip[MAX_CASCADES];
uniform vec4 uCascadeDepths[MAX_CASCADES];  // view depths (m): near, blendStart, split; -
// x: texel edge (m), y: depth span of the map (m), z: filter radius (texels), w: resolution
uniform vec4 uCascadeParams[MAX_CASCADES];
uniform vec3 uViewPosition;  // camera, world metres
uniform vec3 uViewForward;   // camera's unit forward axis

float cascadeVisibility(int i, vec3 p, vec3 ng, vec3 l) {
  vec4 params = uCascadeParams[i];
  vec2 bias = shadowBias(params.x, ng, l, params.z);
  vec3 q = (uCascadeWorldToClip[i] * vec4(p + ng * bias.x, 1.0)).xyz * 0.5 + 0.5;
  q.z -= bias.y / params.y;
  // Tile i of the 2×2 atlas; taps are kept half a texel inside it.
  vec2 tile = vec2(float(i & 1), float(i >> 1)) * 0.5;
  float texel = 0.5 / params.w;  // one cascade texel in atlas coordinates
  vec2 lo = tile + vec2(0.5 * texel), hi = tile + vec2(0.5 - 0.5 * texel);
  vec2 uv = tile + q.xy * 0.5;
  gCostShadowTaps += uShadowFilter == 0 ? 1 : 16;
  if (uShadowFilter == 0) return texture(uCascadeMap, vec3(clamp(uv, lo, hi), q.z));
  mat2 rotation = shadowKernelRotation();
  float lit = 0.0;
  for (int k = 0; k < 16; ++k) {
    vec2 tap = uv + rotation * POISSON16[k] * (params.z * texel);
    lit += texture(uCascadeMap, vec3(clamp(tap, lo, hi), q.z));
  }
  return lit / 16.0;
}

// V in [0, 1] of the cascaded light at receiver p (world metres) with unit geometric normal ng;
// l is the unit direction towards the light.
float directionalVisibility(vec3 p, vec3 ng, vec3 l) {
  if (uCascadeCount == 0) return 1.0;
  float z = dot(p - uViewPosition, uViewForward);
  for (int i = 0; i < uCascadeCount; ++i) {
    vec4 depths = uCascadeDepths[i];
    bool last = i + 1 == uCascadeCount;
    if (z > depths.z && !last) continue;
    float v = cascadeVisibility(i, p, ng, l);
    if (z > depths.y && !last) {
      float w = clamp((z - depths.y) / (depths.z - depths.y), 0.0, 1.0);
      v = mix(v, cascadeVisibility(i + 1, p, ng, l), w);
    }
    return v;
  }
  return 1.0;
}
