// Visibility of VPLs: low-resolution depth cubes at chosen VPLs (up to 4 per VPL group, each for
// a part of the group's members), all in one depth array, layer 6·cube + face
// (engine/render/vpl_shadow_maps.h; docs/vpl.md "Visibility"). Depth is distance from the map
// origin / far.
#include "shadow_common.glsl"
#include "cube_face.glsl"


uniform sampler2DArrayShadow uVplShadowMap;
uniform int uVplShadowEnabled;  // 0: every group sees everything (visibility 1)
uniform int uVplShadowCount;    // cubes
// Per cube: the map origin (metres): its VPL lifted along its normal.
uniform vec3 uVplShadowOrigin[MAX_VPL_SHADOW_CUBES];
// x: texel edge per metre of distance (2/resolution, at a face's centre), y: far (m),
// z: origin offset (m), w: resolution (texels per face side)
uniform vec4 uVplShadowParams;

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
  vec3 uvFace = cubeFaceUv(d);
  float layer = float(cube * 6) + uvFace.z;
  gCostShadowTaps += 1;
  return texture(uVplShadowMap, vec4(uvFace.xy, layer, reference));
}
