// A virtual point light (instant radiosity, Keller 1997): a point on a diffuse surface that
// re-emits, as a cosine (Lambertian) emitter on the side of `normal`, the light a light path
// brought there. Header only and GL-free: the baker makes them (baker/vpl), the bake folder
// stores them (engine/bake_folder/vpl_file.h), the path tracer can sample them for checks
// (baker/trace/light_sampler.h) and the renderer draws them.
//
// Convention (derived in docs/vpl.md): `flux` Φ is the flux the VPL re-emits, W per linear-RGB
// channel, already multiplied by the albedo ρ_vpl of the surface it sits on. Its radiant
// intensity is I(ω) = Φ/π · cosθ_vpl (so ∫ I dω over the hemisphere = Φ), and the radiance it
// adds, reflected by a Lambertian surface of albedo ρ_x at x, is
//     L(x) = Φ/π · cosθ_vpl · cosθ_x / d² · ρ_x/π        [W/(sr·m²)]
// (irradiance E(x) = Φ/π · cosθ_vpl · cosθ_x / d², W/m²), with d the distance, θ_vpl the angle
// at the VPL between its normal and x, θ_x the angle at x between its normal and the VPL.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>

#include <glm/glm.hpp>

namespace bounce {

struct Vpl {
  glm::vec3 position{0.0f};            // world, metres
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit; the side the VPL emits into
  glm::vec3 flux{0.0f};                // Φ, W per channel, albedo of its surface included
  // The light path it ends (a VPL set is a set of light-path prefixes): `from` is where its
  // incoming segment started (world, metres: the light's sample point for a bounce-1 VPL, the
  // previous VPL of the path otherwise) and `path` the path's index. The VPLs of one path are
  // consecutive and in path order; an object placed across from → position blocks this VPL and
  // every later one of its path (vpl_runtime/vpl_occlusion.h). Merged VPLs (representatives) have
  // none.
  glm::vec3 from{0.0f};
  uint32_t path = 0;
};

// The light one VPL brings to a receiver, W/m² per channel.
struct VplIrradiance {
  glm::dvec3 irradiance{0.0};  // E, clamped when r > 0
  glm::dvec3 removed{0.0};     // what the clamp took away: E_unclamped − E
  VplIrradiance& operator+=(const VplIrradiance& o) {
    irradiance += o.irradiance;
    removed += o.removed;
    return *this;
  }
};

// The irradiance `vpl` gives at x (unit normal n), unoccluded, with the geometry term capped at
// 1/r² (r2 = r², the clamp distance squared; 0: no cap; docs/vpl.md, "The clamp"):
//     E = Φ/π · cosθ_vpl · cosθ_x / max(d², r²),    removed = Φ/π · cosθ_vpl · cosθ_x / d² − E.
// nullopt when nothing arrives: x behind the VPL, the VPL behind x, the two at one point or
// a distance or cosine that is not finite (the caller need not test visibility then). The one CPU
// statement of the formula: the baker's gather (baker/vpl/vpl_gather.h), the renderer's CPU sums
// (vpl_runtime/vpl_groups.h) and the path tracer's VPL light (trace/path_tracer.h) use it;
// shaders/vpl.glsl is its GLSL twin.
inline std::optional<VplIrradiance> vplIrradiance(const Vpl& vpl, glm::dvec3 x, glm::dvec3 n,
                                                  double r2) {
  const glm::dvec3 d = glm::dvec3(vpl.position) - x;
  const double d2 = glm::dot(d, d);
  if (!(d2 > 0.0) || !std::isfinite(d2)) return std::nullopt;
  const double dist = std::sqrt(d2);
  const double cosX = glm::dot(n, d) / dist;
  const double cosV = -glm::dot(glm::dvec3(vpl.normal), d) / dist;
  if (!(cosX > 0.0) || !(cosV > 0.0)) return std::nullopt;
  // I(ω) = Φ/π · cosθ_vpl (W/sr); E = I · cosθ_x / d².
  const glm::dvec3 intensity = glm::dvec3(vpl.flux) * (cosV / std::numbers::pi);
  const glm::dvec3 unclamped = intensity * (cosX / d2);
  VplIrradiance e;
  e.irradiance = intensity * (cosX / std::max(d2, r2));
  e.removed = unclamped - e.irradiance;
  return e;
}

// The VPL of `members` (not empty) nearest `point`: a point on a real surface and its normal,
// for a group whose representative, a centroid, may lie inside an object (floor VPLs on both
// sides of a block); the VPL shadow maps put a group's cube there (docs/vpl.md "Visibility").
inline const Vpl& nearestVpl(std::span<const Vpl> members, glm::vec3 point) {
  std::size_t best = 0;
  float bestDistance = 0.0f;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const glm::vec3 d = members[i].position - point;
    if (i == 0 || glm::dot(d, d) < bestDistance) {
      best = i;
      bestDistance = glm::dot(d, d);
    }
  }
  return members[best];
}

}  // namespace bounce
