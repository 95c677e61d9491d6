// What every shadow map lookup shares (docs/shadows.md derives each constant).
//
// Bias, in texels of the map. w = the texel's edge in metres at the receiver's distance from
// the light; θ = angle between the geometric normal ng and the direction to the light; R = the
// filter radius in texels (0 for one hardware tap). A lookup compares the receiver against
// depths stored up to R_eff = R + 1.5 texels away (the Poisson taps lie within R; each is a
// bilinear 2×2 comparison whose texel centres lie within √2 texels), where a plane at incidence
// θ is up to R_eff·w·tanθ nearer (to first order; a plane's distance is convex across the map,
// so the second order only moves it away). Two terms cover it, each guarded by a test
// (tests/render/shadow_test.cpp, shadow_bias_test.cpp):
//   normal offset  o = R_eff · w · sinθ   along ng: seen from the light, the offset point lies
//                  o/cosθ = R_eff·w·tanθ in front of its own plane, at any incidence (ShadowAcne
//                  fails without it), and it vanishes at normal incidence, where a slab one texel
//                  thick keeps its shadow (ThinSlab fails with o constant);
//   depth bias     b = w/4   ties, float rounding and the creases of concave receivers
//                  (ConcaveReceiver and VplShadow.NoSelfShadowAtAConcaveCorner fail without it).
// A slope-scaled depth bias (+0.1·w·tanθ) was removed: no plane, concave pipe or round room
// showed acne without it once the kernel lay within R (docs/shadows.md lists what was tried).
// A shadow touching its caster starts b·sinθ ≤ 0.25 texel late. Both terms scale with w: a
// finer map shifts edges less.
#include "cost.glsl"

uniform int uShadowFilter;  // 0: one hardware 2×2 tap; 1: 16 rotated Poisson taps

// 16 points of a Poisson disk in the unit circle (the outermost at radius 1, minimum spacing
// ≈ 0.37), so a kernel of radius R reads no tap beyond R texels: the reach R + 1.5 above and the
// spot map's margin of R + 2 texels rely on it.
const vec2 POISSON16[16] = vec2[](
    vec2(-0.76342630, -0.32340690), vec2(0.76631937, -0.62313577), vec2(-0.07632843, -0.75319272),
    vec2(0.27956106, 0.23816350), vec2(-0.74224974, 0.37093962), vec2(-0.66084860, -0.71245785),
    vec2(-0.31020785, 0.22429795), vec2(0.79003047, 0.61306758), vec2(0.35920391, -0.79025054),
    vec2(0.43554244, -0.38392241), vec2(-0.21473556, -0.33950832), vec2(0.64183039, 0.15471019),
    vec2(-0.19603055, 0.80803882), vec2(-0.65976039, 0.74102609), vec2(0.16195482, 0.63732328),
    vec2(0.11656363, -0.11427525));

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
  float reach = (uShadowFilter == 1 ? radius : 0.0) + 1.5;
  return vec2(reach * w * sinTheta, 0.25 * w);
}
