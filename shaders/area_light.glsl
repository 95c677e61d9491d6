// Area lights: emissive triangles of uniform radiance L (W/(sr·m²)), unshadowed. The
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

// Clips triangle q (relative to p) against the half-space n·x ≥ 0: at most 4 vertices remain.
int clipToUpperHemisphere(vec3 q[3], vec3 n, out vec3 clipped[4]) {
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    vec3 a = q[i];
    vec3 b = q[(i + 1) % 3];
    float da = dot(n, a);
    float db = dot(n, b);
    if (da >= 0.0) clipped[count++] = a;
    if ((da >= 0.0) != (db >= 0.0)) clipped[count++] = a + (b - a) * (da / (da - db));
  }
  return count;
}

// E/L = ½ |Σ γ_i n·û_i| for the clipped polygon: its projected solid angle (sr), π × the
// point-to-polygon form factor.
float polygonIrradiancePerRadiance(vec3 q[4], int count, vec3 n) {
  float sum = 0.0;
  for (int i = 0; i < count; ++i) {
    vec3 a = q[i];
    vec3 b = q[(i + 1) % count];
    vec3 c = cross(a, b);
    float s = length(c);
    if (s > 0.0) sum += atan(s, dot(a, b)) * dot(n, c) / s;
  }
  return 0.5 * abs(sum);
}

vec3 areaIrradiance(vec3 p, vec3 n) {
  vec3 irradiance = vec3(0.0);
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
    vec3 q[3] = vec3[3](v0 - p, v1 - p, v2 - p);
    vec3 clipped[4];
    int count = clipToUpperHemisphere(q, n, clipped);
    if (count < 3) continue;
    irradiance += radiance.rgb * polygonIrradiancePerRadiance(clipped, count, n);
  }
  return irradiance;
}
