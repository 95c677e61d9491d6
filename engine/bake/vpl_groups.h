// The renderer's VPL set, GL-free so that it is tested without GL (tests/bake_io):
//
// VplGroups: the VPLs split into K ≤ 64 coarse groups (groupVpls, bake/vpl_reduce.h), reordered
// so that each group's members are contiguous, and one representative per group: Σ flux (W per
// channel), the luminance-weighted centroid, the normalised flux-weighted mean normal
// (mergeVpls). The representatives are what per-group visibility (one shadow map per group) and
// the far field use.
//
// VplLightCuts: a per-cell lightcut on a world-space grid over the scene bounds. For a cell of
// centre q and half-diagonal h, a group of bounding radius s around its representative at c is
//   far  when |c − q| − h > κ·s: evaluated as its representative alone,
//   near otherwise:              expanded into its members.
// Every receiver x in the cell is then at distance d ≥ κ·s from a far group's centroid. The
// centroid is flux-weighted, so the first-order term of the kernel's Taylor expansion around c
// cancels (exactly for the luminance weights; per channel when the members' colours agree) and
// the error a far group adds is the second-order term, O((s/d)²) ≤ O(1/κ²) of its light
// (docs/vpl.md, "Culling"). Near groups are exact. A receiver outside the grid uses the nearest
// cell (the bound no longer holds there).
//
// Light table: the N reordered VPLs, then the K representatives (index N + g). A cut entry is a
// range of the light table: (first, count): a near group (its members) or a far one (N + g, 1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake/vpl.h"

namespace bounce {

inline constexpr std::size_t kMaxVplGroups = 64;

struct VplGroup {
  uint32_t first = 0;  // members: lights()[first, first + count)
  uint32_t count = 0;
  float radius = 0.0f;  // s: largest member distance from the representative, m
};

class VplGroups {
 public:
  VplGroups() = default;
  // Groups `vpls` into min(k, kMaxVplGroups) groups (fewer when there are fewer VPLs; k ≥ 1).
  VplGroups(std::span<const Vpl> vpls, std::size_t k);

  // The N VPLs, group by group, then the K representatives: the table the shader reads.
  std::span<const Vpl> lights() const { return lights_; }
  std::span<const Vpl> vpls() const { return std::span(lights_).first(vplCount_); }
  std::span<const Vpl> representatives() const { return std::span(lights_).subspan(vplCount_); }
  std::span<const VplGroup> groups() const { return groups_; }
  // The group of light-table entry i (a VPL or a representative).
  uint32_t groupOf(std::size_t light) const { return lightGroup_[light]; }
  std::size_t vplCount() const { return vplCount_; }
  std::size_t groupCount() const { return groups_.size(); }

 private:
  std::vector<Vpl> lights_;
  std::vector<uint32_t> lightGroup_;
  std::vector<VplGroup> groups_;
  std::size_t vplCount_ = 0;
};

struct VplLightCutSettings {
  float kappa = 4.0f;  // far when the cell is more than κ group radii away; ∞: no culling
  int maxCellsPerAxis = 16;
};

struct VplLightCuts {
  glm::vec3 origin{0.0f};    // grid corner, m
  glm::vec3 cellSize{1.0f};  // m, > 0 on every axis
  glm::ivec3 cells{1};       // cells per axis
  // Per cell (x fastest, then y, then z): its entries, (first, count) into `entries`.
  std::vector<glm::uvec2> cellEntries;
  // Light-table ranges, (first, count).
  std::vector<glm::uvec2> entries;

  // The cell holding p (clamped to the grid), as an index into cellEntries.
  std::size_t cellOf(glm::vec3 p) const;
  // Σ count over a cell's entries: how many lights a receiver there evaluates.
  std::size_t lightsEvaluated(std::size_t cell) const;
};

// The grid over [lo, hi] (metres; a degenerate axis gets one cell) with, per cell, every group
// once: far groups as their representative, near ones expanded.
VplLightCuts buildVplLightCuts(const VplGroups& groups, glm::vec3 lo, glm::vec3 hi,
                               const VplLightCutSettings& settings);

struct VplIrradianceSum {
  glm::dvec3 irradiance{0.0};  // E = Σ Φ/π · cosθ_y · cosθ_x / max(d², r²), W/m²
  glm::dvec3 removed{0.0};  // Σ Φ/π · cosθ_y · cosθ_x · (1/d² − 1/max(d², r²)), W/m²
};

// What shaders/vpl.glsl computes at receiver p (unit normal n) with visibility 1, on the CPU:
// the lights of p's cell, clamp distance r (m; 0: none).
VplIrradianceSum vplCutIrradiance(const VplGroups& groups, const VplLightCuts& cuts, glm::vec3 p,
                                  glm::vec3 n, float clampDistance);
// The same sum over `lights` (every one evaluated).
VplIrradianceSum vplIrradianceSum(std::span<const Vpl> lights, glm::vec3 p, glm::vec3 n,
                                  float clampDistance);

}  // namespace bounce
