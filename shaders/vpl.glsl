// Virtual point lights (engine/render/vpl_pass.h, docs/vpl.md): the irradiance E (W/m²) they
// give a surface at world point p with unit shading normal n and geometric normal ng,
//   E(p) = Σ_i Φ_i/π · max(cosθ_y,0) · max(cosθ_x,0) / max(d², r²) · V_i(p)
// with Φ_i the VPL's flux (W per channel, its surface's albedo included), θ_y the angle at the
// VPL between its normal and p, θ_x the angle at p between n and the VPL, d the distance (m),
// r the clamp distance (m) and V_i the visibility of the light's shadow cube (vplVisibility,
// defined in vpl_shadows.glsl; one cube per part of a group, render/vpl_shadow_maps.h). A Lambertian surface of albedo ρ reflects ρ/π · E. The lights summed are
// those of p's grid cell (vpl_runtime/vpl_groups.h): the cell's cut of each group's VPL tree, near
// leaves VPL by VPL, far nodes as their representative (flux-weighted centroid, Σ flux); every
// light carries the index of its shadow cube for the visibility. Must match vplCutIrradiance
// (engine/vpl_runtime/vpl_groups.cpp).
//
// The light table's VPL sections (light_table.glsl, engine/render/light_table.h):
//   lights: 3 texels per light: (position m, cube), (unit normal, 0), (Φ W, 0); the N VPLs
//           group by group, then the K group representatives, then the other tree nodes'
//           representatives;
//   cuts:   per cell (first entry, entry count), cells x fastest, then the entries, each a
//           range of lights (first, count); entry indices count from the section's first texel.

#include "cost.glsl"

// Visibility (0..1) of shadow cube `cube` from p; defined in vpl_shadows.glsl.
float vplVisibility(int cube, vec3 p, vec3 ng);

uniform vec3 uVplGridOrigin;   // m
uniform vec3 uVplCellSize;     // m
uniform ivec3 uVplGridCells;   // cells per axis
uniform float uVplClampDistance;  // r, m

// E (clamped, as above), what the clamp removed: Σ Φ/π·cos·cos·(1/d² − 1/max(d², r²))·V, and
// the squared distance (m²) to the nearest light that gave p any (1e30 when none did).
void vplIrradianceNearest(vec3 p, vec3 n, vec3 ng, out vec3 clamped, out vec3 removed,
                          out float nearestD2) {
  clamped = vec3(0.0);
  removed = vec3(0.0);
  nearestD2 = 1e30;
  ivec3 c = clamp(ivec3(floor((p - uVplGridOrigin) / uVplCellSize)), ivec3(0), uVplGridCells - 1);
  int cell = c.x + uVplGridCells.x * (c.y + uVplGridCells.y * c.z);
  uvec2 cellEntries = vplCutRange(cell);
  float r2 = uVplClampDistance * uVplClampDistance;
  for (uint e = cellEntries.x; e < cellEntries.x + cellEntries.y; ++e) {
    uvec2 range = vplCutRange(int(e));
    for (uint i = range.x; i < range.x + range.y; ++i) {
      gCostVpls += 1;
      vec4 positionGroup = vplTexel(int(i), 0);
      vec3 d = positionGroup.xyz - p;
      float d2 = dot(d, d);
      if (!(d2 > 0.0)) continue;
      float invD = inversesqrt(d2);
      float cosX = dot(n, d) * invD;
      float cosY = -dot(vplTexel(int(i), 1).xyz, d) * invD;
      if (cosX <= 0.0 || cosY <= 0.0) continue;
      float v = vplVisibility(int(positionGroup.w), p, ng);  // .w: the cube
      if (v <= 0.0) continue;
      // I(ω) = Φ/π · cosθ_y (W/sr); E = I · cosθ_x / max(d², r²).
      vec3 intensity = vplTexel(int(i), 2).rgb * (cosY / PI) * (cosX * v);
      float clampedD2 = max(d2, r2);
      clamped += intensity / clampedD2;
      removed += intensity * ((clampedD2 - d2) / (d2 * clampedD2));
      nearestD2 = min(nearestD2, d2);
    }
  }
}

void vplIrradianceParts(vec3 p, vec3 n, vec3 ng, out vec3 clamped, out vec3 removed) {
  float nearestD2;
  vplIrradianceNearest(p, n, ng, clamped, removed, nearestD2);
}

vec3 vplIrradiance(vec3 p, vec3 n, vec3 ng) {
  vec3 clamped, removed;
  vplIrradianceParts(p, n, ng, clamped, removed);
  return clamped;
}
