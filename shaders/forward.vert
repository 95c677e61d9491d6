#version 330 core
// Scene vertices are already in world space (the renderer flattens instances on upload).
layout(location = 0) in vec3 aPosition;  // metres
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uViewProjection;

out vec3 vWorldPosition;
out vec3 vNormal;
out vec2 vUv;

void main() {
  vWorldPosition = aPosition;
  vNormal = aNormal;
  vUv = aUv;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
