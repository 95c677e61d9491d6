#version 330 core
// VPL shadow cubes (engine/render/vpl_shadow_maps.h): the caster's distance to the map origin /
// far, as shadow_depth.frag, but only in front of the VPL's tangent plane through the origin.
// Nothing behind that plane can occlude a receiver in front of it (the segment from the origin
// to such a receiver lies wholly in front), and the VPL lights nothing behind it; dropping it
// removes the VPL's own surface from its map, which would otherwise fill the texels along the
// map's horizon and shadow the receivers there.
in vec3 vWorldPosition;

uniform vec3 uLightPosition;  // the map origin, metres
uniform float uFar;           // metres
uniform vec3 uVplNormal;      // unit

void main() {
  if (dot(vWorldPosition - uLightPosition, uVplNormal) < 0.0) discard;
  gl_FragDepth = length(vWorldPosition - uLightPosition) / uFar;
}
