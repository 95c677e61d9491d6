// Area lights: emissive triangles of uniform radiance L (W/(sr·m²)). The unshadowed
// irradiance they give a Lambertian receiver at p with unit normal n is exact (Lambert's
// contour integral for a polygon, the emitter first clipped to the receiver's upper
// hemisphere n·(x − p) ≥ 0):
//   E = L · ½ · |Σ_i γ_i · n·(q_i × q_{i+1}) / |q_i × q_{i+1}||,   q_i = v_i − p,
// γ_i the angle between q_i and q_{i+1} (taken as atan2(|q_i×q_{i+1}|, q_i·q_{i+1}), exact
// also for small angles). The absolute value makes the winding irrelevant: a planar polygon
// not containing p projects to one side. An emitter gives light only to the side its front face
// (counter-clockwise) looks at, or both sides when double-sided.
//
// Emitter table (uEmitters, RGBA32F, 4 texels per row): first one row per triangle,
//   texels 0..2: world vertices (xyz, metres); texel 3: radiance (rgb), w = 1 if double-sided;
// then one row per area light (engine/scene/area_lights.h: emitters cut by their shape),
//   texel 0: (first triangle row, end row, 1 if its direct light is baked (Material::bakeDirect)
//   else 0, its outline's corners k or 0 for none); texel 1: its unit front normal (xyz) and its
//   outline's first corner (w); texel 2: its radiance (rgb), w = 1 if double-sided; the static
//   lights come first. A baked light is skipped once a bake is attached (uHasBake): its direct light is in
//   the lightmap.
// then the outlines' corners (engine/scene/area_light_outline.h), 4 a row: a planar light with
// an outline is evaluated as one polygon of k edges (the contour integral is additive, interior
// edges cancel), else triangle by triangle.

#include "cost.glsl"
#include "light_grid.glsl"

uniform sampler2D uEmitters;
uniform int uEmitterCount;    // triangle rows
uniform int uAreaLightCount;  // light rows, after the triangles

// One edge's term γ · n·(a×b)/|a×b| of the contour sum (0 for a degenerate edge).
float edgeTerm(vec3 a, vec3 b, vec3 n) {
  vec3 c = cross(a, b);
  float s = length(c);
  return s > 0.0 ? atan(s, dot(a, b)) * dot(n, c) / s : 0.0;
}

// Where the edge from a to b crosses the horizon plane n·x = 0 (da, db: the ends' heights).
vec3 horizonCrossing(vec3 a, vec3 b, float da, float db) {
  return a + (b - a) * (da / (da - db));
}

// E/L = ½ |Σ γ_i n·û_i| for triangle (a, b, c) (relative to p) clipped to n·x ≥ 0: the projected
// solid angle (sr) of its visible part, π × the point-to-polygon form factor. Clipping a
// triangle by a plane leaves it whole, a triangle (one vertex above) or a quad (two above); the
// vertices are rotated so the odd one out comes first, keeping the winding.
float clippedTriangleIrradiancePerRadiance(vec3 a, vec3 b, vec3 c, vec3 n) {
  float da = dot(n, a), db = dot(n, b), dc = dot(n, c);
  bool ua = da >= 0.0, ub = db >= 0.0, uc = dc >= 0.0;
  int above = int(ua) + int(ub) + int(uc);
  if (above == 0) return 0.0;
  if (above == 3) return 0.5 * abs(edgeTerm(a, b, n) + edgeTerm(b, c, n) + edgeTerm(c, a, n));
  // Rotate (a, b, c) so that `a` is the vertex alone on its side.
  bool alone = above == 1;  // the lone vertex is above when one is above, below when two are
  if (ub == alone) {
    vec3 t = a; a = b; b = c; c = t;
    float dt = da; da = db; db = dc; dc = dt;
  } else if (uc == alone) {
    vec3 t = c; c = b; b = a; a = t;
    float dt = dc; dc = db; db = da; da = dt;
  }
  vec3 ab = horizonCrossing(a, b, da, db);
  vec3 ca = horizonCrossing(c, a, dc, da);
  float sum = above == 1
                  ? edgeTerm(a, ab, n) + edgeTerm(ab, ca, n) + edgeTerm(ca, a, n)
                  : edgeTerm(ab, b, n) + edgeTerm(b, c, n) + edgeTerm(c, ca, n) + edgeTerm(ca, ab, n);
  return 0.5 * abs(sum);
}

// E of one triangle (row `i`) at p, unshadowed (0 when p is behind a single-sided emitter).
vec3 emitterTriangleIrradiance(int i, vec3 p, vec3 n) {
  vec3 v0 = texelFetch(uEmitters, ivec2(0, i), 0).xyz;
  vec3 v1 = texelFetch(uEmitters, ivec2(1, i), 0).xyz;
  vec3 v2 = texelFetch(uEmitters, ivec2(2, i), 0).xyz;
  vec4 radiance = texelFetch(uEmitters, ivec2(3, i), 0);
  // Signed distance of p from the emitter's plane, along its front normal. Points on the plane
  // (the emitter itself, coplanar neighbours) see it edge-on and receive nothing.
  vec3 front = normalize(cross(v1 - v0, v2 - v0));
  float height = dot(front, p - v0);
  if (abs(height) < 1e-5 || (height < 0.0 && radiance.w < 0.5)) return vec3(0.0);
  return radiance.rgb * clippedTriangleIrradiancePerRadiance(v0 - p, v1 - p, v2 - p, n);
}

// Where the polygon clipped to n·x ≥ 0 goes next: Sutherland–Hodgman against one plane, its
// output corners walked on the fly; `last` and `first` the output so far (`count` of them).
void emitClippedCorner(vec3 corner, vec3 n, inout vec3 last, inout vec3 first, inout int count,
                       inout float sum) {
  if (count == 0) first = corner;
  else sum += edgeTerm(last, corner, n);
  last = corner;
  ++count;
}

// E/L of light `light`'s outline (corners `first` .. first + k − 1 after the light rows, counter-
// clockwise about its front normal) at p: ½ |Σ γ_i n·û_i| over the outline clipped to the
// receiver's upper hemisphere (a clipped polygon may run along the horizon and back: those edges
// cancel). 0 when p is on its plane or behind a single-sided light.
vec3 outlineIrradiance(int light, int k, vec3 p, vec3 n) {
  int row = uEmitterCount + light;
  vec4 plane = texelFetch(uEmitters, ivec2(1, row), 0);  // front normal, first corner
  vec3 front = plane.xyz;
  vec4 radiance = texelFetch(uEmitters, ivec2(2, row), 0);
  int base = uEmitterCount + uAreaLightCount, first = int(plane.w);
  vec3 a = texelFetch(uEmitters, ivec2((first + k - 1) & 3, base + ((first + k - 1) >> 2)), 0).xyz;
  float height = dot(front, p - a);
  if (abs(height) < 1e-5 || (height < 0.0 && radiance.w < 0.5)) return vec3(0.0);
  a -= p;
  float da = dot(n, a);
  vec3 last = vec3(0.0), start = vec3(0.0);
  int count = 0;
  float sum = 0.0;
  for (int i = first; i < first + k; ++i) {
    vec3 b = texelFetch(uEmitters, ivec2(i & 3, base + (i >> 2)), 0).xyz - p;
    float db = dot(n, b);
    if ((da >= 0.0) != (db >= 0.0))
      emitClippedCorner(horizonCrossing(a, b, da, db), n, last, start, count, sum);
    if (db >= 0.0) emitClippedCorner(b, n, last, start, count, sum);
    a = b;
    da = db;
  }
  if (count > 2) sum += edgeTerm(last, start, n);
  return radiance.rgb * (0.5 * abs(sum));
}

// Σ over the area lights of the fragment's cluster (light_grid.glsl) of V_l · E_l: E_l the exact unshadowed irradiance of light l's triangles,
// V_l its visible fraction: baked per lightmap texel for static lights on a static surface
// (baked_visibility.glsl; times the dynamic instances' own cube when the light has one), else
// from its shadow map when it has one (shadow_area.glsl), else 1
// (ng: the receiver's geometric normal; baked: the bake's texels around its lightmap UV).
// `fromTexels`: the static lights' V_l · E_l is read from the lightmap's texels instead
// (lightmap.glsl, render/static_direct_texels.h), so such a light is evaluated here only when a
// dynamic caster shadows it, as the correction V_l · E_l · (s − 1), s its cube's visible
// fraction: a static pixel pays for what moves, not for the static lights.
vec3 areaIrradiance(LightList lights, vec3 p, vec3 n, vec3 ng, BakedVisibilityTexels baked,
                    bool fromTexels) {
  vec3 irradiance = vec3(0.0);
  int count = lights.all ? uAreaLightCount : lights.areaCount;
  // Lists ascend and the static lights have the first indices: walked from the end, the first
  // static light in the texels ends the walk when no dynamic caster needs a correction, so the
  // loop runs over the dynamic lights only (a shader runs a loop until every lane has left it).
  bool staticInTexels = fromTexels && uHasBakedVisibility && !uAreaDynamicShadows;
  for (int k = count - 1; k >= 0; --k) {
    int l = areaLightIndex(lights, k);  // its own row: baked visibility and shadows by index
    if (staticInTexels && l < uBakedLightCount) break;
    vec4 rows = texelFetch(uEmitters, ivec2(0, uEmitterCount + l), 0);
    if (rows.z > 0.5 && uHasBake) continue;
    bool visibilityBaked = uHasBakedVisibility && l < uBakedLightCount;
    bool inTexels = fromTexels && visibilityBaked;
    int slot = areaShadowSlot(int(rows.x));
    // The dynamic cube only where a dynamic instance may stand between p and the light.
    bool dynamicShadow = uAreaDynamicShadows && slot >= 0 && dynamicCasterBetween(slot, p);
    if (inTexels && !dynamicShadow) continue;  // all of it is in the texels
    gCostLights += 1;
    vec3 e = vec3(0.0);
    if (rows.w > 0.5)
      e = outlineIrradiance(l, int(rows.w), p, n);
    else
      for (int i = int(rows.x); i < int(rows.y); ++i) e += emitterTriangleIrradiance(i, p, n);
    if (e == vec3(0.0)) continue;
    if (visibilityBaked) {
      // The static occluders are baked; the dynamic ones come from their own cubes.
      e *= bakedVisibility(baked, l, true);
      if (dynamicShadow) {
        float s = areaVisibility(slot, p, ng, true);
        e *= inTexels ? s - 1.0 : s;
      }
    } else if (slot >= 0) {
      e *= areaVisibility(slot, p, ng, false);
    }
    irradiance += e;
  }
  return irradiance;
}
