#version 330 core
// Stores the caster's distance to the light, divided by the map's reach: depth ∈ [0,1] is
// linear in metres, so biases are metres too (shadow_common.glsl).
in vec3 vWorldPosition;

uniform vec3 uLightPosition;  // metres
uniform float uFar;           // metres

void main() {
  gl_FragDepth = length(vWorldPosition - uLightPosition) / uFar;
}
