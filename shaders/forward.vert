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
// A dynamic instance's VPL light per vertex (render/vpl_vertex_light.h): this draw's corner k
// is vertex uVplCornerVertex[k], whose light is texel uVplVertexFirst + vertex of the target.
uniform bool uHasVplVertexLight;
uniform usamplerBuffer uVplCornerVertex;
uniform sampler2D uVplVertexLight;  // rgb: E, W/m²; a: the nearest light's distance, m
uniform int uVplVertexFirst;

// To forward.geom, which hands them on per triangle.
out vec3 vsWorldPosition;
out vec3 vsNormal;
out vec2 vsUv;
out vec2 vsLightmapUv;
out vec4 vsVplVertexLight;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vsWorldPosition = world.xyz;
  // Unit per corner before interpolation, as the path tracer's world normals are.
  vsNormal = normalize(uNormalMatrix * aNormal);
  vsUv = aUv;
  vsLightmapUv = aLightmapUv;
  vsVplVertexLight = vec4(0.0);
  if (uHasVplVertexLight) {
    int v = uVplVertexFirst + int(texelFetch(uVplCornerVertex, gl_VertexID).x);
    vsVplVertexLight = texelFetch(uVplVertexLight,
                                  ivec2(v % VPL_VERTEX_LIGHT_WIDTH, v / VPL_VERTEX_LIGHT_WIDTH), 0);
  }
  gl_Position = uViewProjection * world;
}
