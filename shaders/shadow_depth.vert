#version 330 core
// Shadow-map casters: each instance with its own model matrix, seen from the light.
// Attribute locations: engine/gl/vertex_attributes.h.
layout(location = 0) in vec3 aPosition;  // metres, object space

uniform mat4 uModel;           // object → world
uniform mat4 uViewProjection;  // world → the map's clip space

out vec3 vWorldPosition;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
  gl_Position = uViewProjection * world;
}
