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
// Emitter table (uEmitters, RGBA32F, 4 texels per row, one row per triangle):
//   texels 0..2: world vertices (xyz, metres); texel 3: radiance (rgb), w = 1 if double-sided.

uniform sampler2D uEmitters;
uniform int uEmitterCount;

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

// Unshadowed E of every emitter triangle, each times the visible fraction V of the area light it
// belongs to when that light has a shadow map (shadow_area.glsl; ng: the receiver's geometric
// normal). V is evaluated once per light and fragment, when its first triangle needs it.
vec3 areaIrradiance(vec3 p, vec3 n, vec3 ng) {
  vec3 irradiance = vec3(0.0);
  float visibility[MAX_AREA_SHADOWS];
  for (int s = 0; s < MAX_AREA_SHADOWS; ++s) visibility[s] = -1.0;
  for (int i = 0; i < uEmitterCount; ++i) {
    vec3 v0 = texelFetch(uEmitters, ivec2(0, i), 0).xyz;
    vec3 v1 = texelFetch(uEmitters, ivec2(1, i), 0).xyz;
    vec3 v2 = texelFetch(uEmitters, ivec2(2, i), 0).xyz;
    vec4 radiance = texelFetch(uEmitters, ivec2(3, i), 0);
    // Signed distance of p from the emitter's plane, along its front normal. Points on the plane
    // (the emitter itself, coplanar neighbours) see it edge-on and receive nothing.
    vec3 front = normalize(cross(v1 - v0, v2 - v0));
    float height = dot(front, p - v0);
    if (abs(height) < 1e-5 || (height < 0.0 && radiance.w < 0.5)) continue;
    float e = clippedTriangleIrradiancePerRadiance(v0 - p, v1 - p, v2 - p, n);
    if (e <= 0.0) continue;
    int slot = areaShadowSlot(i);
    if (slot >= 0) {
      if (visibility[slot] < 0.0) visibility[slot] = areaVisibility(slot, p, ng);
      e *= visibility[slot];
    }
    irradiance += radiance.rgb * e;
  }
  return irradiance;
}
