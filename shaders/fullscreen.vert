#version 330 core
// One triangle covering the viewport, corners from gl_VertexID: (-1,-1), (3,-1), (-1,3).
out vec2 vUv;  // (0,0) at the bottom-left of the viewport

void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  vUv = corner * 0.5 + 0.5;
  gl_Position = vec4(corner, 0.0, 1.0);
}
