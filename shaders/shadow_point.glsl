// Point-light shadows: a cube map around the light storing distance/far
// (engine/render/point_shadow_maps.h). Needs shadow_common.glsl.

uniform samplerCubeShadow uPointShadowMap[MAX_POINT_SHADOWS];
// x: texel edge per metre of distance (2/resolution at a face's centre), y: far (m),
// z: filter radius (texels), w: resolution (texels per face side)
uniform vec4 uPointShadowParams[MAX_POINT_SHADOWS];

float pointShadowTaps(samplerCubeShadow map, vec3 d, float reference, float step) {
  gCostShadowTaps += uShadowFilter == 0 ? 1 : 16;
  if (uShadowFilter == 0) return texture(map, vec4(d, reference));
  // The kernel lies in the plane perpendicular to d; `step` is its radius in metres at |d|.
  vec3 axis = abs(d.y) < 0.99 * length(d) ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(axis, d));
  vec3 b = normalize(cross(d, t));
  mat2 rotation = shadowKernelRotation();
  float lit = 0.0;
  for (int k = 0; k < 16; ++k) {
    vec2 o = rotation * POISSON16[k] * step;
    lit += texture(map, vec4(d + t * o.x + b * o.y, reference));
  }
  return lit / 16.0;
}

// Fraction of the cube that sees p (1 = lit), for point light `slot` at `lightPosition`.
float pointShadow(int slot, vec3 p, vec3 ng, vec3 lightPosition) {
  vec4 params = uPointShadowParams[slot];
  vec3 toLight = lightPosition - p;
  float distance = length(toLight);
  float w = params.x * distance;
  vec2 bias = shadowBias(w, ng, toLight / distance, params.z);
  vec3 d = p + ng * bias.x - lightPosition;
  float reference = (length(d) - bias.y) / params.y;
  float step = params.z * w;
  if (slot == 0) return pointShadowTaps(uPointShadowMap[0], d, reference, step);
  return pointShadowTaps(uPointShadowMap[1], d, reference, step);
}
