// Visibility of VPL groups: one low-resolution depth cube per group representative, all in one
// depth array, layer 6·group + face (engine/render/vpl_shadow_maps.h; docs/vpl.md
// "Visibility"). Depth is distance from the map origin / far.
#include "shadow_common.glsl"

const int MAX_VPL_SHADOW_GROUPS = 64;      // kMaxVplShadowGroups
const float VPL_SHADOW_HORIZON_LIFT = 1.5;  // kVplShadowHorizonLiftTexels

uniform sampler2DArrayShadow uVplShadowMap;
uniform int uVplShadowEnabled;  // 0: every group sees everything (visibility 1)
uniform int uVplShadowCount;    // groups with a map
// Per group: xyz the map origin (metres, the representative lifted along its normal), w its
// unit normal packed by vplShadowPackNormal (octahedral, 12 + 12 bits, an integer < 2^24).
uniform vec4 uVplShadowGroup[MAX_VPL_SHADOW_GROUPS];
// x: texel edge per metre of distance (2/resolution, at a face's centre), y: far (m),
// z: origin offset (m), w: resolution (texels per face side)
uniform vec4 uVplShadowParams;

vec3 vplShadowUnpackNormal(float code) {
  float qx = floor(code / 4096.0);
  float qy = code - qx * 4096.0;
  vec2 o = vec2(qx, qy) / 4095.0 * 2.0 - 1.0;
  vec3 n = vec3(o, 1.0 - abs(o.x) - abs(o.y));
  if (n.z < 0.0) {
    vec2 s = vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    n.xy = (1.0 - abs(n.yx)) * s;
  }
  return normalize(n);
}

// Face of GL's cube order (+X, −X, +Y, −Y, +Z, −Z) that direction d falls in (major axis), and
// d's texture coordinates in it, as cubeFaceShadowView renders the face: forward F, up U,
// lookAt's right s = F × U and up u = s × F; a 90° projection gives ndc = (s·d, u·d) / (F·d).
vec3 vplShadowFaceUv(vec3 d) {
  vec3 a = abs(d);
  int face;
  vec3 f, up;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x > 0.0 ? 0 : 1;
    f = vec3(sign(d.x), 0.0, 0.0);
    up = vec3(0.0, -1.0, 0.0);
  } else if (a.y >= a.z) {
    face = d.y > 0.0 ? 2 : 3;
    f = vec3(0.0, sign(d.y), 0.0);
    up = vec3(0.0, 0.0, sign(d.y));
  } else {
    face = d.z > 0.0 ? 4 : 5;
    f = vec3(0.0, 0.0, sign(d.z));
    up = vec3(0.0, -1.0, 0.0);
  }
  vec3 s = cross(f, up);
  vec3 u = cross(s, f);
  vec2 ndc = vec2(dot(s, d), dot(u, d)) / dot(f, d);
  return vec3(ndc * 0.5 + 0.5, float(face));
}

// 1 = group `group`'s representative sees p (receiver with unit geometric normal ng, facing
// the VPL), 0 = occluded; the bilinear 2×2 comparison in between.
float vplVisibility(int group, vec3 p, vec3 ng) {
  if (uVplShadowEnabled == 0 || group < 0 || group >= uVplShadowCount) return 1.0;
  vec4 g = uVplShadowGroup[group];
  vec3 origin = g.xyz;
  vec3 n = vplShadowUnpackNormal(g.w);
  vec3 toVpl = origin - p;
  float distance = length(toVpl);
  if (distance <= 0.0) return 1.0;
  float w = uVplShadowParams.x * distance;  // texel edge (m) at the receiver's distance
  vec2 bias = shadowBias(w, ng, toVpl / distance, 0.0);
  vec3 d = p + ng * bias.x - origin;
  float reference = (length(d) - bias.y) / uVplShadowParams.y;
  // Lift the lookup at least VPL_SHADOW_HORIZON_LIFT texels above the VPL's horizon: nearer
  // to it the 2×2 footprint reaches texels below the horizon, which see the VPL's own surface.
  float lift = length(d) * VPL_SHADOW_HORIZON_LIFT * uVplShadowParams.x;
  float height = dot(d, n);
  if (height < lift) d += n * (lift - height);
  vec3 uvFace = vplShadowFaceUv(d);
  float layer = float(group * 6) + uvFace.z;
  return texture(uVplShadowMap, vec4(uvFace.xy, layer, reference));
}
