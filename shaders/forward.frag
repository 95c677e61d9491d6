#version 330 core
// One forward pass: outgoing radiance (W/(sr·m²)) of a Lambertian surface,
//   L_o = ρ/π · (E_punctual + E_area + E_baked) + L_e,
// into a linear float target; E_baked is the lightmap's irradiance on static surfaces, and the
// mode picks the terms (lightmap.glsl); static instances without a lightmap region read it from
// their irradiance probes (probes.glsl); dynamic instances (and every surface in the vpl mode)
// get their indirect light from the virtual point lights instead (vpl.glsl). ρ = albedo × base-colour texel (linear), clamped to [0,1] as the
// path tracer does; L_e the surface's own emission (front face; both when double-sided).
// Each fragment shades only the lights of its view cluster (light_grid.glsl).
// Punctual lights are shadowed by their maps (shadows.glsl); area lights by their baked
// visibility on static surfaces (baked_visibility.glsl), else by their maps (shadow_area.glsl:
// percentage-closer soft shadows). The cost mode writes what the fragment evaluated instead
// (cost.glsl): lights, VPLs and shadow-map taps as R, G, B.
#include "cost.glsl"
#include "baked_visibility.glsl"
#include "lights.glsl"
#include "shadows.glsl"
#include "probes.glsl"
#include "lightmap.glsl"
#include "area_light.glsl"
#include "static_direct.glsl"
#include "vpl.glsl"
#include "vpl_shadows.glsl"
#include "view_modes.glsl"

// Centroid: with multisampling a pixel on a triangle's edge whose centre lies outside it is
// shaded at a covered sample, so the position (shadow and visibility lookups) and the lightmap
// UV (which would read the chart's padding or its neighbour) stay on the triangle.
centroid in vec3 vWorldPosition;
centroid in vec3 vNormal;
in vec2 vUv;
centroid in vec2 vLightmapUv;
in vec3 vWorldPositionAtCentre;  // the same at the pixel centre, for screen derivatives
in vec2 vLightmapUvAtCentre;
flat in vec2 vTriangleLightmapUv[3];  // the triangle's three lightmap coordinates
flat in int vTriangle;                 // the triangle's number in the draw (forward.geom)
centroid in vec3 vCornerWeights;       // the fragment's barycentric weights of its corners
centroid in vec3 vVplVertexLight;      // a dynamic instance's VPL light from its corners, W/m²
flat in int vVplFromVertices;          // this triangle reads it (forward.geom)

uniform vec3 uAlbedo;              // ρ, linear RGB
uniform vec3 uEmission;            // W/(sr·m²)
uniform bool uHasAlbedoTexture;
uniform sampler2D uAlbedoTexture;  // linear RGB texels

out vec4 fragRadiance;

// The point of triangle (a, b, c) nearest to p (p itself inside; degenerate triangles too).
vec2 closestOnSegment(vec2 p, vec2 a, vec2 b) {
  vec2 ab = b - a;
  float t = dot(ab, ab) > 0.0 ? clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0) : 0.0;
  return a + t * ab;
}
vec2 closestPointInTriangle(vec2 p, vec2 a, vec2 b, vec2 c) {
  float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  float wa = (b.x - p.x) * (c.y - p.y) - (b.y - p.y) * (c.x - p.x);
  float wb = (c.x - p.x) * (a.y - p.y) - (c.y - p.y) * (a.x - p.x);
  float wc = area - wa - wb;
  bool inside = area > 0.0 ? (wa >= 0.0 && wb >= 0.0 && wc >= 0.0)
                           : area < 0.0 && wa <= 0.0 && wb <= 0.0 && wc <= 0.0;
  if (inside) return p;
  vec2 ab = closestOnSegment(p, a, b), bc = closestOnSegment(p, b, c), ca = closestOnSegment(p, c, a);
  vec2 best = dot(p - ab, p - ab) < dot(p - bc, p - bc) ? ab : bc;
  return dot(p - ca, p - ca) < dot(p - best, p - best) ? ca : best;
}

void main() {
  // Single-sided back faces are culled, so a back face here is double-sided: shade its side.
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  // The triangle's own (geometric) normal on the shaded side, for the shadow bias. From the
  // pixel-centre position: a centroid value moves within the pixel at a triangle's edge, so its
  // screen derivatives there mix positions along the edge and tilt the normal anywhere (under
  // 4x MSAA the bias then pushed lookups through a 2 cm wall: lit pixels along the dark room's
  // corners in bench_thin_wall_leak).
  vec3 ng = cross(dFdx(vWorldPositionAtCentre), dFdy(vWorldPositionAtCentre));
  ng = dot(ng, ng) > 0.0 ? normalize(ng) : n;
  if (dot(ng, n) < 0.0) ng = -ng;
  // Every lightmap lookup reads at the centroid's coordinate clamped into the triangle
  // (forward.geom says why), so its bilinear taps stay on the triangle's chart and its ring.
  vec2 lightmapUv = closestPointInTriangle(vLightmapUv, vTriangleLightmapUv[0],
                                           vTriangleLightmapUv[1], vTriangleLightmapUv[2]);
  vec3 albedo = uAlbedo;
  if (uHasAlbedoTexture) albedo = clamp(albedo * texture(uAlbedoTexture, vUv).rgb, 0.0, 1.0);
  // The inspection views that are no light at all (uniform branches: derivatives stay defined).
  if (uLightingMode == LIGHTING_TEXEL_DENSITY) {
    fragRadiance = vec4(texelDensityView(vLightmapUvAtCentre, vWorldPositionAtCentre), 1.0);
    return;
  }
  if (uLightingMode == LIGHTING_CASCADES) {
    fragRadiance = vec4(cascadeView(vWorldPosition), 1.0);
    return;
  }
  vec3 direct = vec3(0.0);
  if (modeUsesDirectLight()) {
    LightList lights = clusterLights(vWorldPosition);
    BakedVisibilityTexels baked;
    if (uHasBakedVisibility)
      baked = uHasCornerVisibility ? cornerVisibilityTexels(vTriangle, vCornerWeights)
                                   : bakedVisibilityTexels(lightmapUv, uLightmapSize);
    // A static front face reads the static lights' direct light where it was computed
    // once, from texels or corners (static_direct.glsl; a back face of a double-sided surface is
    // not the side it was computed for).
    bool staticPrecomputed = staticDirectPrecomputed(vTriangle) && gl_FrontFacing;
    direct = punctualIrradiance(lights, vWorldPosition, n, ng, baked, staticPrecomputed) +
             areaIrradiance(lights, vWorldPosition, n, ng, baked, staticPrecomputed);
    if (staticPrecomputed) direct += staticDirect(lightmapUv, vTriangle, vCornerWeights, n);
  }
  vec3 vplClamped = vec3(0.0), vplRemoved = vec3(0.0);
  if (modeUsesVpls()) {
    // A dynamic instance's front face reads the VPLs gathered at its vertices where its
    // triangle is small enough (forward.geom, render/vpl_vertex_light.h); the vpl modes show
    // every pixel's own gather.
    if (vVplFromVertices != 0 && gl_FrontFacing && uLightingMode != LIGHTING_VPL &&
        uLightingMode != LIGHTING_VPL_CLAMP)
      vplClamped = vVplVertexLight;
    else
      vplIrradianceParts(vWorldPosition, n, ng, vplClamped, vplRemoved);
  }
  vec3 probe = vec3(0.0);
  if (uHasProbes) probe = probeIrradiance(vWorldPosition, n);
  // The cost view: what the lines above evaluated (cost.glsl), as raw counts.
  if (uLightingMode == LIGHTING_COST) {
    fragRadiance = vec4(float(gCostLights), float(gCostVpls), float(gCostShadowTaps), 1.0);
    return;
  }
  fragRadiance = vec4(
      shadeForMode(albedo, direct, uEmission, lightmapUv, vplClamped, vplRemoved, probe), 1.0);
}
