// Soft shadows of area lights (emissive polygons): the visible fraction V of a light seen from a
// receiver, to multiply the light's exact unshadowed irradiance (area_light.glsl). Percentage-
// closer soft shadows (Fernando 2005) on a depth cube map taken from the light's centre c, with
// the filter region shaped like the light itself (engine/render/area_lights.h):
//   1. blocker search: the K fixed points x_k on the light, each moved towards the receiver p
//      onto the segment x_k→p at the distance d_min from the light (b_k = x_k + (p − x_k)·d/d_R),
//      is the widest cone through which anything nearer than d_min … d_R could block; the mean
//      distance d_B of what the map holds in front of the receiver along those directions;
//   2. filter: the same points at d = d_B: V = the share of directions c→b_k along which nothing
//      lies in front of the receiver. For a blocker parallel to the light this is exactly the
//      visible share of the light's area; the penumbra's width grows as a·(d_R − d_B)/d_B.
// "In front of the receiver" compares with the receiver's own plane along each direction
// (receiver-plane depth), so a large filter region over a flat floor does not shadow the floor;
// the depth bias is the one every map shares (shadow_common.glsl's shadowBias) with the cube's
// texel edge w = texelAngle·distance. d_min = max(light radius, d_R/5): blockers nearer the light
// than that (penumbrae over 4× the light's size) are not searched for. Needs shadow_common.glsl.

const int MAX_AREA_SHADOWS = 3;      // texture units kAreaShadow0.. (render/texture_units.h)
const int AREA_SHADOW_SAMPLES = 32;  // K, points per light (kAreaShadowSamples)

uniform int uAreaShadowCount;
uniform samplerCube uAreaShadowMap0;  // distance from c / far, read raw (no comparison)
uniform samplerCube uAreaShadowMap1;
uniform samplerCube uAreaShadowMap2;
uniform vec3 uAreaShadowOrigin[MAX_AREA_SHADOWS];  // c, metres
// x: far (m), y: face size (texels), z: light radius (m), w: unused
uniform vec4 uAreaShadowParams[MAX_AREA_SHADOWS];
uniform vec2 uAreaShadowRows[MAX_AREA_SHADOWS];  // the light's emitter-table rows [first, end)
uniform vec3 uAreaShadowPoints[MAX_AREA_SHADOWS * AREA_SHADOW_SAMPLES];  // x_k, world metres

// Distance (metres) from the light's centre to the nearest surface along `direction`.
float areaShadowDistance(int light, vec3 direction) {
  float stored = light == 0   ? texture(uAreaShadowMap0, direction).r
                 : light == 1 ? texture(uAreaShadowMap1, direction).r
                              : texture(uAreaShadowMap2, direction).r;
  return stored * uAreaShadowParams[light].x;
}

// Distance along the unit direction w from c to the receiver's plane (through p, normal n), or
// a huge value when w does not reach that plane (everything along w is on c's side of it). c may
// lie on either side: a light straddling the receiver's plane lights it with its upper part.
float receiverPlaneDistance(vec3 c, vec3 w, vec3 p, vec3 n) {
  float along = dot(n, w);
  float t = abs(along) > 1e-8 ? dot(n, p - c) / along : -1.0;
  return t > 0.0 ? t : 1e30;
}

// True when the map holds a surface in front of the receiver's plane along c→b.
bool blockedTowards(int light, vec3 c, vec3 b, vec3 p, vec3 n, float texelAngle, out float hit) {
  vec3 w = normalize(b - c);
  float receiver = receiverPlaneDistance(c, w, p, n);
  hit = areaShadowDistance(light, w);
  float bias = shadowBias(texelAngle * min(receiver, 1e6), n, -w, 0.0).y;
  return hit < receiver - bias;
}

// V in [0, 1] for shadowed light `light` (0 ≤ light < uAreaShadowCount) at receiver p, normal n.
float areaVisibility(int light, vec3 p, vec3 n) {
  vec3 c = uAreaShadowOrigin[light];
  vec4 params = uAreaShadowParams[light];
  float dR = length(p - c);
  if (dR <= 0.0) return 1.0;
  float texelAngle = 2.0 / params.y;  // radians per texel at a face's centre
  float dMin = min(max(params.z, 0.2 * dR), dR);
  int base = light * AREA_SHADOW_SAMPLES;

  float blockerSum = 0.0;
  int blockers = 0;
  for (int k = 0; k < AREA_SHADOW_SAMPLES; ++k) {
    vec3 x = uAreaShadowPoints[base + k];
    float hit;
    if (blockedTowards(light, c, x + (p - x) * (dMin / dR), p, n, texelAngle, hit)) {
      blockerSum += hit;
      ++blockers;
    }
  }
  if (blockers == 0) return 1.0;
  float dB = clamp(blockerSum / float(blockers), dMin, dR);

  int visible = 0;
  for (int k = 0; k < AREA_SHADOW_SAMPLES; ++k) {
    vec3 x = uAreaShadowPoints[base + k];
    float hit;
    if (!blockedTowards(light, c, x + (p - x) * (dB / dR), p, n, texelAngle, hit)) ++visible;
  }
  return float(visible) / float(AREA_SHADOW_SAMPLES);
}

// The shadowed light (0 ≤ slot < uAreaShadowCount) whose emitter-table row `row` is, or −1.
int areaShadowSlot(int row) {
  for (int slot = 0; slot < uAreaShadowCount; ++slot) {
    vec2 rows = uAreaShadowRows[slot];
    if (float(row) >= rows.x && float(row) < rows.y) return slot;
  }
  return -1;
}
