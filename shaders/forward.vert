#version 330 core
// Scene vertices in object space; each instance is drawn with its own model matrix.
// Attribute locations: engine/gl/vertex_attributes.h.
layout(location = 0) in vec3 aPosition;    // metres, object space
layout(location = 1) in vec3 aNormal;      // unit, object space
layout(location = 2) in vec2 aUv;          // material UV
layout(location = 3) in vec2 aLightmapUv;  // lightmap atlas UV; (0,0) when the instance has none

uniform mat4 uModel;         // object → world
uniform mat3 uNormalMatrix;  // inverse transpose of uModel's linear part
uniform mat4 uViewProjection;

centroid out vec3 vWorldPosition;
centroid out vec3 vNormal;
out vec2 vUv;
centroid out vec2 vLightmapUv;
// The same two at the pixel centre (not centroid): their screen derivatives, which centroid
// sampling would bend at triangle edges, give the texel-density view (view_modes.glsl).
out vec3 vWorldPositionAtCentre;
out vec2 vLightmapUvAtCentre;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
  // Unit per corner before interpolation, as the path tracer's world normals are.
  vNormal = normalize(uNormalMatrix * aNormal);
  vUv = aUv;
  vLightmapUv = aLightmapUv;
  vWorldPositionAtCentre = world.xyz;
  vLightmapUvAtCentre = aLightmapUv;
  gl_Position = uViewProjection * world;
}
