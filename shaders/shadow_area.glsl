// Soft shadows of area lights (emissive polygons): the visible fraction V of a light seen from a
// receiver, to multiply the light's exact unshadowed irradiance (area_light.glsl). Percentage-
// closer soft shadows (Fernando 2005) on a depth cube map taken from the light's centre c, with
// the filter region shaped like the light itself (engine/render/area_lights.h):
//   1. blocker search: the K fixed points x_k on the light, each moved towards the receiver p
//      onto the segment x_k→p at the distance d_min from the light (b_k = x_k + (p − x_k)·d/d_R),
//      is the widest cone through which anything nearer than d_min … d_R could block; the mean
//      distance d_B of what the map holds in front of the receiver along those directions;
//   2. filter: the same points at d = d_B: nothing in front of the receiver along c→b_k means
//      x_k is visible. V = Σ w_k·visible_k / Σ w_k with w_k = cosθ_p·cosθ_x/r⁴·… the point-to-
//      point form factor kernel max(n·(x_k−p), 0)·max(±n_L·(p−x_k), 0)/|x_k − p|⁴, so each point
//      counts for the irradiance it brings (a wall sees the light's near edge far more strongly
//      than its far edge), and V·E is the shadowed polygon integral in the limit of many points.
//      For a blocker parallel to the light the filter region is exactly the light's shadow
//      footprint; the penumbra's width grows as a·(d_R − d_B)/d_B.
// "In front of the receiver" compares with the receiver's own plane along each direction
// (receiver-plane depth), so a large filter region over a flat floor does not shadow the floor;
// the depth bias is the one every map shares (shadow_common.glsl's shadowBias) with the cube's
// texel edge w = texelAngle·distance. d_min = max(light radius, d_R/5): blockers nearer the light
// than that (penumbrae over 4× the light's size) are not searched for. Needs shadow_common.glsl.

#include "cube_face.glsl"


uniform int uAreaShadowCount;  // slots [0, count) may hold a light (rows (0, 0): none)
// Every slot's cube in one array, layer 6·slot + face (cube_face.glsl): distance from c / far,
// read raw (no comparison). One texture unit and one fetch per lookup for any number of slots
// (GLSL 3.30 cannot index an array of samplers by a variable).
uniform sampler2DArray uAreaShadowMaps;
// The same cubes with only the dynamic instances drawn (uAreaDynamicShadows): what a static
// surface with baked visibility still needs from the maps.
uniform bool uAreaDynamicShadows;
uniform sampler2DArray uAreaDynamicShadowMaps;
uniform vec3 uAreaShadowOrigin[MAX_AREA_SHADOWS];  // c, metres
// x: far (m), y: face size (texels), z: light radius (m), w: unused
uniform vec4 uAreaShadowParams[MAX_AREA_SHADOWS];
uniform vec2 uAreaShadowRows[MAX_AREA_SHADOWS];  // the light's emitter-table rows [first, end)
// xyz: the light's unit front normal n_L (0 when its faces cancel), w: 1 if double-sided
uniform vec4 uAreaShadowNormal[MAX_AREA_SHADOWS];
uniform vec3 uAreaShadowPoints[MAX_AREA_SHADOWS * AREA_SHADOW_SAMPLES];  // x_k, world metres
// The dynamic instances' bounding spheres (centre, radius; m); count −1: too many, test none.
uniform int uDynamicCasterCount;
uniform vec4 uDynamicCasters[MAX_DYNAMIC_CASTERS];

// Whether a dynamic instance may stand between receiver p and shadowed light `light`. The light
// lies within its radius r_L of its centre c, so every segment from p to a point of it lies in
// the cone from p around p→c of half-angle α, sin α = r_L/|c − p|; a caster sphere (s, R) at
// distance L from p, seen within β of its centre (sin β = R/L), meets that cone only if the
// angle θ between s − p and c − p is ≤ α + β. Otherwise it blocks none of the light, and the
// dynamic cube's V is 1 without a tap.
bool dynamicCasterBetween(int light, vec3 p) {
  if (uDynamicCasterCount < 0) return true;
  vec3 axis = uAreaShadowOrigin[light] - p;
  float distance = length(axis);
  if (distance <= uAreaShadowParams[light].z) return true;
  axis /= distance;
  float sinA = uAreaShadowParams[light].z / distance, cosA = sqrt(1.0 - sinA * sinA);
  for (int i = 0; i < uDynamicCasterCount; ++i) {
    vec4 s = uDynamicCasters[i];
    vec3 v = s.xyz - p;
    float l = length(v);
    if (l <= s.w) return true;
    float sinB = s.w / l, cosB = sqrt(1.0 - sinB * sinB);
    float cosAB = cosA * cosB - sinA * sinB;  // cos(α + β); α + β ≥ π/2 lets cos θ ≥ 0 through
    if (dot(v, axis) >= l * cosAB) return true;
  }
  return false;
}

// Distance (metres) from the light's centre to the nearest surface along `direction` (of the
// dynamic instances alone when `dynamicOnly`).
float areaShadowDistance(int light, vec3 direction, bool dynamicOnly) {
  vec3 uvFace = cubeFaceUv(direction);
  vec3 at = vec3(uvFace.xy, float(6 * light) + uvFace.z);
  gCostShadowTaps += 1;
  float stored = dynamicOnly ? texture(uAreaDynamicShadowMaps, at).r : texture(uAreaShadowMaps, at).r;
  return stored * uAreaShadowParams[light].x;
}

// How far along the unit direction w from c a surface must be to count as "behind the
// receiver": the receiver's plane (through p, normal n) where w meets it nearer than p itself
// (c may lie on either side: a light straddling the plane lights it with its upper part), else
// p's own distance dR. Beyond dR the plane is no reference: along a direction grazing the plane
// or leaving it, the map sees other surfaces (a floor meeting the wall) that lie past the
// segment from the light to p and block nothing.
float receiverDistance(vec3 c, vec3 w, vec3 p, vec3 n, float dR) {
  float along = dot(n, w);
  float t = abs(along) > 1e-8 ? dot(n, p - c) / along : -1.0;
  return t > 0.0 ? min(t, dR) : dR;
}

// True when the map holds a surface in front of the receiver along c→b.
bool blockedTowards(int light, vec3 c, vec3 b, vec3 p, vec3 n, float dR, float texelAngle,
                    bool dynamicOnly, out float hit) {
  vec3 w = normalize(b - c);
  float receiver = receiverDistance(c, w, p, n, dR);
  hit = areaShadowDistance(light, w, dynamicOnly);
  float bias = shadowBias(texelAngle * receiver, n, -w, 0.0).y;
  return hit < receiver - bias;
}

// V in [0, 1] for shadowed light `light` (0 ≤ light < uAreaShadowCount) at receiver p, normal n,
// from every caster or (dynamicOnly) from the dynamic instances alone.
float areaVisibility(int light, vec3 p, vec3 n, bool dynamicOnly) {
  vec3 c = uAreaShadowOrigin[light];
  vec4 params = uAreaShadowParams[light];
  float dR = length(p - c);
  if (dR <= 0.0) return 1.0;
  float texelAngle = 2.0 / params.y;  // radians per texel at a face's centre
  float dMin = min(max(params.z, 0.2 * dR), dR);
  int base = light * AREA_SHADOW_SAMPLES;
  float hit;
  // uShadowFilter 0 (hard): the light as a point at its centre, one lookup.
  if (uShadowFilter == 0) return blockedTowards(light, c, p, p, n, dR, texelAngle, dynamicOnly, hit) ? 0.0 : 1.0;

  float blockerSum = 0.0;
  int blockers = 0;
  for (int k = 0; k < AREA_SHADOW_SAMPLES; ++k) {
    vec3 x = uAreaShadowPoints[base + k];
    if (blockedTowards(light, c, x + (p - x) * (dMin / dR), p, n, dR, texelAngle, dynamicOnly,
                       hit)) {
      blockerSum += hit;
      ++blockers;
    }
  }
  if (blockers == 0) return 1.0;
  float dB = clamp(blockerSum / float(blockers), dMin, dR);

  vec4 lightNormal = uAreaShadowNormal[light];
  float visible = 0.0, total = 0.0;
  for (int k = 0; k < AREA_SHADOW_SAMPLES; ++k) {
    vec3 x = uAreaShadowPoints[base + k];
    vec3 d = x - p;
    float r2 = dot(d, d);
    float emitterCos = dot(lightNormal.xyz, -d);
    emitterCos = lightNormal.w > 0.5 || lightNormal.xyz == vec3(0.0) ? abs(emitterCos) : max(emitterCos, 0.0);
    float w = max(dot(n, d), 0.0) * emitterCos / (r2 * r2);
    if (w <= 0.0) continue;
    total += w;
    if (!blockedTowards(light, c, x + (p - x) * (dB / dR), p, n, dR, texelAngle, dynamicOnly,
                        hit)) visible += w;
  }
  return total > 0.0 ? visible / total : 1.0;
}

// The shadowed light (0 ≤ slot < uAreaShadowCount) whose emitter-table row `row` is, or −1.
int areaShadowSlot(int row) {
  for (int slot = 0; slot < uAreaShadowCount; ++slot) {
    vec2 rows = uAreaShadowRows[slot];
    if (float(row) >= rows.x && float(row) < rows.y) return slot;
  }
  return -1;
}
