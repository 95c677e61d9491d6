#version 330 core
// Each triangle unchanged, plus its three lightmap coordinates, flat: forward.frag clamps its
// lightmap lookups into the triangle. A fragment that covers only some of a pixel's samples is
// shaded at its centroid, which should lie inside the triangle; llvmpipe's centroid values at
// 4x MSAA edges do not (they read texels of other charts: the thin-wall rooms' corner pixels
// showed 31% of the lit room's mean), and a pixel-centre value can lie half a pixel outside,
// several texels where texels are smaller than pixels. The clamp holds on any driver.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vsWorldPosition[];
in vec3 vsNormal[];
in vec2 vsUv[];
in vec2 vsLightmapUv[];
in vec4 vsVplVertexLight[];

centroid out vec3 vWorldPosition;
centroid out vec3 vNormal;
out vec2 vUv;
centroid out vec2 vLightmapUv;
// The same two at the pixel centre (not centroid): their screen derivatives, which centroid
// sampling would bend at triangle edges, give the geometric normal and the texel-density view.
out vec3 vWorldPositionAtCentre;
out vec2 vLightmapUvAtCentre;
flat out vec2 vTriangleLightmapUv[3];
// The triangle's number in its draw (its mesh's `indices` order: the draws are de-indexed) and
// the fragment's barycentric weights of its corners: the probe-lit instances' baked visibility
// is per triangle corner (baked_visibility.glsl). Centroid, as the position: inside the triangle.
flat out int vTriangle;
centroid out vec3 vCornerWeights;
// A dynamic instance's VPL light interpolated from its corners (render/vpl_vertex_light.h), and
// whether this triangle reads it: not when its longest edge h exceeds VPL_MAX_EDGE_OVER_DISTANCE
// times the nearest light's distance d at any corner (interpolation's error grows as (h/d)²).
centroid out vec3 vVplVertexLight;
flat out int vVplFromVertices;

uniform bool uHasVplVertexLight;

void main() {
  int fromVertices = 0;
  if (uHasVplVertexLight) {
    vec3 a = vsWorldPosition[0], b = vsWorldPosition[1], c = vsWorldPosition[2];
    float h2 = max(dot(b - a, b - a), max(dot(c - b, c - b), dot(a - c, a - c)));
    float d = min(vsVplVertexLight[0].a, min(vsVplVertexLight[1].a, vsVplVertexLight[2].a));
    fromVertices = h2 <= VPL_MAX_EDGE_OVER_DISTANCE * VPL_MAX_EDGE_OVER_DISTANCE * d * d ? 1 : 0;
  }
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    vWorldPosition = vsWorldPosition[i];
    vNormal = vsNormal[i];
    vUv = vsUv[i];
    vLightmapUv = vsLightmapUv[i];
    vWorldPositionAtCentre = vsWorldPosition[i];
    vLightmapUvAtCentre = vsLightmapUv[i];
    vTriangleLightmapUv[0] = vsLightmapUv[0];
    vTriangleLightmapUv[1] = vsLightmapUv[1];
    vTriangleLightmapUv[2] = vsLightmapUv[2];
    vTriangle = gl_PrimitiveIDIn;
    vCornerWeights = vec3(i == 0, i == 1, i == 2);
    vVplVertexLight = vsVplVertexLight[i].rgb;
    vVplFromVertices = fromVertices;
    EmitVertex();
  }
  EndPrimitive();
}
