// Irradiance probes: the baked light of the static instances the atlas leaves without a lightmap
// region (atlas/atlas.h: too small or thin for texels). Each such instance has a small grid of
// probes around it; each probe holds the irradiance E(n) (W/m², per linear-RGB channel) a
// surface of unit normal n would receive at its point, as the first two bands (L1) of its real
// spherical-harmonic expansion. GL-free; the baker fills it (baker/bake/irradiance_probes.h), the
// bake folder stores it (probe_file.h), the renderer reads it (shaders/probes.glsl).
//
// Convention (docs/probes.md). Real SH basis on the unit sphere, n = (x, y, z):
//   Y00 = 1/(2√π) = 0.282095,  Y1−1 = c·y,  Y10 = c·z,  Y11 = c·x,  c = √(3/(4π)) = 0.488603.
// The coefficients are those of E itself, E_lm = ∫ E(n) Y_lm(n) dn over the sphere of normals
// (W/m² · sr^½ in the basis' normalisation), so the reconstruction is
//   E(n) ≈ Y00·E00 + c·(E11·x + E1−1·y + E10·z)          (W/m², clamped at 0 by the renderer).
// In terms of the incoming radiance's coefficients L_lm (W/(sr·m²)), E_lm = Â_l·L_lm with the
// clamped-cosine lobe's convolution constants Â0 = π and Â1 = 2π/3 (Ramamoorthi & Hanrahan
// 2001): a uniform radiance L gives E00 = π·L/Y00 and E(n) = π·L for every n.
//
// A probe holds the light the lightmap holds (texel_irradiance.h): light that reflected at least
// once, plus the direct light of the lights and emitters marked baked-only.
//
// The same instances' direct light is drawn live, and the static lights' visibility they need is
// baked per triangle corner (ProbeVisibility below), as a lightmapped surface's is per texel.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/light_visibility.h"

namespace bounce {

inline constexpr float kShY00 = 0.282094791773878f;  // 1/(2√π)
inline constexpr float kShY1 = 0.488602511902920f;   // √(3/(4π))

// The four L1 coefficients of E, per RGB channel, in the order E00, E1−1, E10, E11 (W/m²).
struct ProbeIrradiance {
  std::array<glm::vec3, 4> sh{};
  bool operator==(const ProbeIrradiance&) const = default;
};

// The four real SH basis values at unit direction n, in ProbeIrradiance's order.
inline std::array<float, 4> shBasisL1(glm::vec3 n) {
  return {kShY00, kShY1 * n.y, kShY1 * n.z, kShY1 * n.x};
}

// E(n), W/m² per channel, from the L1 coefficients (not clamped).
inline glm::vec3 probeIrradianceAt(const ProbeIrradiance& p, glm::vec3 n) {
  const std::array<float, 4> y = shBasisL1(n);
  return y[0] * p.sh[0] + y[1] * p.sh[1] + y[2] * p.sh[2] + y[3] * p.sh[3];
}

// One instance's probes: counts.x × counts.y × counts.z probes at origin + (i, j, k) ⊙ spacing,
// x fastest, starting at probe `first` of IrradianceProbes::probes. Every count is at least 2,
// so any point of the grid's box lies in a cell of 8 probes.
struct ProbeGrid {
  uint32_t instance = 0;  // index into Scene::instances (the scene file's numbering)
  uint32_t first = 0;
  glm::uvec3 counts{2u};
  glm::vec3 origin{0.0f};   // m, world
  glm::vec3 spacing{0.0f};  // m, > 0 on every axis
  // m: the renderer reads the grid at p + normalOffset·n, so a surface reads the probes on its
  // lit side of a thin object (the grid's box is the instance's grown by this much).
  float normalOffset = 0.0f;
  // The instance's baked visibility: corners [firstCorner, firstCorner + cornerCount) of
  // ProbeVisibility::corners, 3 per triangle of its mesh in the mesh's `indices` order (corner k
  // of triangle t at 3t + k), or none (cornerCount 0: the bake has no static light to bake).
  uint32_t firstCorner = 0;
  uint32_t cornerCount = 0;
  bool operator==(const ProbeGrid&) const = default;

  uint32_t probeCount() const { return counts.x * counts.y * counts.z; }
  glm::vec3 position(glm::uvec3 cell) const { return origin + glm::vec3(cell) * spacing; }
};

// Baked visibility of the static lights on the probe-lit instances (Unity's shadowmask for
// objects without lightmaps, at the mesh's own resolution): per triangle corner, the (light, V)
// slots of a lightmap texel (light_visibility.h, the same light numbering and kOtherLights
// rule). Corner k of a triangle holds V_l = ∫ b_k E_l vis / ∫ b_k E_l over the triangle, b_k the
// corner's barycentric weight: the visible fraction of the irradiance the part of the triangle
// nearest the corner receives, so V = Σ_k b_k V_k interpolated over the triangle reproduces a
// V that varies linearly across it. The renderer reads it as it reads 3 texels, weighted by the
// fragment's barycentric coordinates (shaders/baked_visibility.glsl).
struct ProbeVisibility {
  uint32_t lightCount = 0;     // static area lights (BakedVisibility::lightCount)
  uint32_t punctualCount = 0;  // punctual lights (BakedVisibility::punctualCount)
  std::vector<TexelVisibility> corners;
  bool operator==(const ProbeVisibility&) const = default;
};

struct IrradianceProbes {
  std::vector<ProbeGrid> grids;  // by instance, ascending
  std::vector<ProbeIrradiance> probes;
  ProbeVisibility visibility;  // empty when the bake has no static light to bake
  bool operator==(const IrradianceProbes&) const = default;
};

}  // namespace bounce
