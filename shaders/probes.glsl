// Irradiance probes (engine/render/probe_pass.h, bake_folder/irradiance_probes.h): the baked
// light of a static instance without a lightmap region. Its grid's probes hold the L1 spherical
// harmonics of E(n) (W/m²); the pixel reads the 8 probes of the grid cell around p + m·n (m the
// grid's normal offset: the surface's own side of a thin object), trilinearly, each probe's
// weight times ((1 + cos)/2)² + 0.05 of the angle between n and the direction to it (a probe
// behind the surface counts little), each probe's E(n) clamped at 0. Constant work per pixel:
// 24 buffer reads, no loop over lights.

uniform samplerBuffer uProbes;  // 3 RGBA32F texels per probe: (Y00·E00, Y1·E11, Y1·E1−1, Y1·E10)
uniform bool uHasProbes;        // this draw: a static instance lit by probes
uniform int uProbeFirst;        // its grid's first probe
uniform ivec3 uProbeCounts;     // probes per axis, each ≥ 2, x fastest
uniform vec3 uProbeOrigin;      // m, probe (0, 0, 0)
uniform vec3 uProbeSpacing;     // m, per axis
uniform float uProbeNormalOffset;  // m

// Probe `index` of the grid: E(n), W/m², clamped at 0.
vec3 probeIrradianceOf(int index, vec3 n) {
  int t = 3 * (uProbeFirst + index);
  vec4 basis = vec4(1.0, n);
  vec3 e = vec3(dot(texelFetch(uProbes, t), basis), dot(texelFetch(uProbes, t + 1), basis),
                dot(texelFetch(uProbes, t + 2), basis));
  return max(e, vec3(0.0));
}

// E(n) at world point p (m) of a surface with unit normal n, W/m².
vec3 probeIrradiance(vec3 p, vec3 n) {
  vec3 q = p + uProbeNormalOffset * n;
  vec3 g = clamp((q - uProbeOrigin) / uProbeSpacing, vec3(0.0), vec3(uProbeCounts - 1));
  ivec3 base = min(ivec3(g), uProbeCounts - 2);
  vec3 f = g - vec3(base);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < 8; ++i) {
    ivec3 corner = ivec3(i & 1, (i >> 1) & 1, i >> 2);
    ivec3 cell = base + corner;
    vec3 along = mix(1.0 - f, f, vec3(corner));
    vec3 toProbe = uProbeOrigin + vec3(cell) * uProbeSpacing - p;
    float facing = dot(toProbe, toProbe) > 0.0 ? 0.5 * (dot(normalize(toProbe), n) + 1.0) : 1.0;
    float w = along.x * along.y * along.z * (facing * facing + 0.05);
    sum += w * probeIrradianceOf(cell.x + uProbeCounts.x * (cell.y + uProbeCounts.y * cell.z), n);
    weights += w;
  }
  return weights > 0.0 ? sum / weights : vec3(0.0);
}
