// Visibility of VPLs: low-resolution depth cubes at chosen VPLs (up to 4 per VPL group, each for
// a part of the group's members), all in one depth array, layer 6·cube + face
// (engine/render/vpl_shadow_maps.h; docs/vpl.md "Visibility"). Depth is distance from the map
// origin / far.
#include "shadow_common.glsl"

const int MAX_VPL_SHADOW_CUBES = 256;  // kMaxVplShadowCubes

uniform sampler2DArrayShadow uVplShadowMap;
uniform int uVplShadowEnabled;  // 0: every group sees everything (visibility 1)
uniform int uVplShadowCount;    // cubes
// Per cube: the map origin (metres): its VPL lifted along its normal.
uniform vec3 uVplShadowOrigin[MAX_VPL_SHADOW_CUBES];
// x: texel edge per metre of distance (2/resolution, at a face's centre), y: far (m),
// z: origin offset (m), w: resolution (texels per face side)
uniform vec4 uVplShadowParams;

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

// 1 = cube `cube` sees p (receiver with unit geometric normal ng, facing the VPL), 0 =
// occluded; the bilinear 2×2 comparison in between.
float vplVisibility(int cube, vec3 p, vec3 ng) {
  if (uVplShadowEnabled == 0 || cube < 0 || cube >= uVplShadowCount) return 1.0;
  vec3 origin = uVplShadowOrigin[cube];
  vec3 toVpl = origin - p;
  float distance = length(toVpl);
  if (distance <= 0.0) return 1.0;
  float w = uVplShadowParams.x * distance;  // texel edge (m) at the receiver's distance
  vec2 bias = shadowBias(w, ng, toVpl / distance, 0.0);
  vec3 d = p + ng * bias.x - origin;
  float reference = (length(d) - bias.y) / uVplShadowParams.y;
  vec3 uvFace = vplShadowFaceUv(d);
  float layer = float(cube * 6) + uvFace.z;
  return texture(uVplShadowMap, vec4(uvFace.xy, layer, reference));
}
