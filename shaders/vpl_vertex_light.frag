#version 330 core
// The VPLs' irradiance at one vertex of a dynamic instance, for its shading normal: exactly the
// sum a pixel there would take (vpl.glsl, clamped, with the shadow cubes), and the distance to
// the nearest light that gave any. One fragment per vertex, texel j = (y − uRow)·width + x of
// the instance's rows (render/vpl_vertex_light.h).
#include "light_table.glsl"
#include "vpl.glsl"
#include "vpl_shadows.glsl"

uniform samplerBuffer uVertices;  // 2 texels per vertex: position (m), unit normal; object space
uniform int uVertexCount;
uniform int uRow;                 // the instance's first row
uniform mat4 uModel;              // object → world
uniform mat3 uNormalMatrix;

out vec4 fragLight;  // rgb: E, W/m²; a: the nearest light's distance, m

void main() {
  int j = (int(gl_FragCoord.y) - uRow) * int(VPL_VERTEX_LIGHT_WIDTH) + int(gl_FragCoord.x);
  if (j >= uVertexCount) {
    fragLight = vec4(0.0);
    return;
  }
  vec3 p = (uModel * vec4(texelFetch(uVertices, 2 * j).xyz, 1.0)).xyz;
  vec3 n = normalize(uNormalMatrix * texelFetch(uVertices, 2 * j + 1).xyz);
  vec3 clamped, removed;
  float nearestD2;
  vplIrradianceNearest(p, n, n, clamped, removed, nearestD2);
  fragLight = vec4(clamped, sqrt(nearestD2));
}
