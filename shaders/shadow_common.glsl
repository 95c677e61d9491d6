// What every shadow map lookup shares (docs/shadows.md derives each constant).
//
// Bias, in texels of the map. w = the texel's edge in metres at the receiver's distance from
// the light; θ = angle between the geometric normal ng and the direction to the light; R = the
// filter radius in texels, R_eff = R + 1 (each tap is a bilinear 2×2 comparison). Within R_eff
// texels of the lookup, a plane at incidence θ departs from the looked-up depth by up to
// R_eff·w·tanθ. Two terms cover it:
//   normal offset  o = R_eff · w · sinθ   along ng: seen from the light, the offset point is
//                                          o/cosθ = R_eff·w·tanθ in front of its own plane;
//   depth bias     b = w · (0.5 + 0.5·min(tanθ, 10))   (slope-scaled; the constant half texel
//                  covers the sphere-vs-plane curvature of distance maps and float rounding).
// Both vanish with the texel size, so a finer map shifts shadow edges less.

uniform int uShadowFilter;  // 0: one hardware 2×2 tap; 1: 16 rotated Poisson taps

// 16 points of a Poisson disk in the unit circle (minimum spacing ≈ 0.37).
const vec2 POISSON16[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

// A per-pixel rotation of the kernel (interleaved gradient noise, Jimenez 2014): turns the
// kernel's banding into fine noise.
mat2 shadowKernelRotation() {
  float angle = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  float c = cos(angle), s = sin(angle);
  return mat2(c, s, -s, c);
}

// x: normal offset (m), y: depth bias (m) for texel edge w (m), unit geometric normal ng, unit
// direction to the light l, filter radius in texels.
vec2 shadowBias(float w, vec3 ng, vec3 l, float radius) {
  float cosTheta = clamp(dot(ng, l), 0.0, 1.0);
  float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
  float tanTheta = min(sinTheta / max(cosTheta, 1e-4), 10.0);
  float reach = (uShadowFilter == 1 ? radius : 0.0) + 1.0;
  return vec2(reach * w * sinTheta, w * (0.5 + 0.5 * tanTheta));
}
