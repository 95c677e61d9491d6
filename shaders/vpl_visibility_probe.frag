#version 330 core
// Reads vplVisibility at listed receivers, one per pixel of an N×1 target (tests and
// debugging: tests/render/vpl_shadow_test.cpp). uReceivers: an N×2 data table, row 0 the
// positions (metres), row 1 the unit geometric normals. Pixel x writes cube uProbeGroup's
// visibility of receiver x into every channel.
#include "vpl_shadows.glsl"

uniform sampler2D uReceivers;
uniform int uProbeGroup;

out vec4 fragColor;

void main() {
  int x = int(gl_FragCoord.x);
  vec3 p = texelFetch(uReceivers, ivec2(x, 0), 0).xyz;
  vec3 ng = texelFetch(uReceivers, ivec2(x, 1), 0).xyz;
  fragColor = vec4(vec3(vplVisibility(uProbeGroup, p, ng)), 1.0);
}
