// The renderer's VPL set, GL-free so that it is tested without GL (tests/bake_io):
//
// VplGroups: the VPLs split into K ≤ 64 coarse groups (groupVpls, vpl_runtime/vpl_reduce.h),
// reordered so that each group's members are contiguous, and one representative per group: Σ flux
// (W per channel), the luminance-weighted centroid, the normalised flux-weighted mean normal
// (mergeVpls). The representatives are what per-group visibility (one shadow map per group) and
// the far field use.
//
// Inside each group the VPLs form a binary tree (split at the median of the longest axis of the
// node's box, down to leaves of ≤ kVplLeafSize VPLs); every node has a representative made the
// same way. A node's members are a contiguous range of the light table.
//
// VplLightCuts: a per-cell lightcut (Walter et al. 2005, with a distance criterion) on a
// world-space grid over the scene bounds. For a cell of centre q and half-diagonal h, each
// group's tree is walked from its root; a node of bounding radius s around its representative
// at c is
//   far  when |c − q| − h > κ·s: evaluated as its representative alone,
//   near otherwise:              its children are walked (a near leaf: its VPLs).
// Every receiver x in the cell is then at distance d ≥ κ·s from a far node's centroid. The
// centroid is flux-weighted, so the first-order term of the kernel's Taylor expansion around c
// cancels (exactly for the luminance weights; per channel when the members' colours agree) and
// the error a far node adds is the second-order term, O((s/d)²) ≤ O(1/κ²) of its light
// (docs/vpl.md, "Culling"). A receiver outside the grid uses the nearest cell (the bound no
// longer holds there). The nodes of a cut cover every VPL exactly once.
//
// Light table: the N reordered VPLs, then the K group representatives (index N + g), then the
// representatives of the other nodes. A cut entry is a range of the light table, (first,
// count): VPLs (a near leaf, consecutive leaves merged) or one representative.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"

namespace bounce {

inline constexpr std::size_t kMaxVplGroups = 64;
inline constexpr uint32_t kVplLeafSize = 4;

struct VplGroup {
  uint32_t first = 0;  // members: lights()[first, first + count)
  uint32_t count = 0;
  float radius = 0.0f;  // s: largest member distance from the representative, m
  uint32_t root = 0;    // its tree's root in VplGroups::nodes()
};

struct VplNode {
  uint32_t first = 0;  // members: lights()[first, first + count) (VPLs)
  uint32_t count = 0;
  uint32_t representative = 0;    // light-table index (the VPL itself when count = 1)
  float radius = 0.0f;            // largest member distance from the representative, m
  int32_t left = -1, right = -1;  // children in nodes(); −1 for a leaf
};

class VplGroups {
 public:
  VplGroups() = default;
  // Groups `vpls` into min(k, kMaxVplGroups) groups (fewer when there are fewer VPLs; k ≥ 1).
  VplGroups(std::span<const Vpl> vpls, std::size_t k);

  // The N VPLs, group by group, then the K group representatives, then the other nodes'
  // representatives: the table the shader reads.
  std::span<const Vpl> lights() const { return lights_; }
  std::span<const Vpl> vpls() const { return std::span(lights_).first(vplCount_); }
  // The K group representatives (one shadow map each): lights()[N, N + K).
  std::span<const Vpl> representatives() const {
    return std::span(lights_).subspan(vplCount_, groups_.size());
  }
  std::span<const VplGroup> groups() const { return groups_; }
  std::span<const VplNode> nodes() const { return nodes_; }
  // The group of light-table entry i (a VPL or a representative).
  uint32_t groupOf(std::size_t light) const { return lightGroup_[light]; }
  std::size_t vplCount() const { return vplCount_; }
  std::size_t groupCount() const { return groups_.size(); }
  // vpls()[i] is input VPL vplOrder()[i].
  std::span<const uint32_t> vplOrder() const { return order_; }
  // The flux (W per channel) of every light-table entry when only the input VPLs with
  // alive[i] ≠ 0 (in input order, vpl_runtime/vpl_occlusion.h) shine: a VPL's own flux or 0, a
  // representative's the sum over its alive members. Positions and normals stay as built.
  std::vector<glm::vec3> lightFluxes(std::span<const uint8_t> alive) const;

 private:
  std::vector<Vpl> lights_;
  std::vector<uint32_t> order_;
  std::vector<uint32_t> lightGroup_;
  std::vector<VplGroup> groups_;
  std::vector<VplNode> nodes_;
  std::size_t vplCount_ = 0;
};

struct VplLightCutSettings {
  float kappa = 4.0f;  // far when the cell is more than κ node radii away; ∞: no culling
  int maxCellsPerAxis = 16;
  // At most this many lights per cell (0: no bound), so that a receiver's cost does not grow
  // with the VPL count. The cut is refined worst node first, by the far-field error estimate
  // lum(Φ)·s²/d⁴ (the second-order term of a node of flux Φ and radius s seen from d), until
  // every node is far, a leaf's VPLs, or the next refinement would pass the bound. Under the
  // bound the cut is the unbounded one. Raised to the group count when below it.
  uint32_t maxLights = 512;
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

// The grid over [lo, hi] (metres; a degenerate axis gets one cell) with, per cell, the cut of
// every group's tree: far nodes as their representative, near leaves as their VPLs (within the
// settings' light bound: the nodes left near when it is reached are their representative).
VplLightCuts buildVplLightCuts(const VplGroups& groups, glm::vec3 lo, glm::vec3 hi,
                               const VplLightCutSettings& settings);

// What shaders/vpl.glsl computes at receiver p (unit normal n) with visibility 1, on the CPU:
// Σ vplIrradiance (bake_folder/vpl.h) over the lights of p's cell, clamp distance r (m; 0: none).
VplIrradiance vplCutIrradiance(const VplGroups& groups, const VplLightCuts& cuts, glm::vec3 p,
                               glm::vec3 n, float clampDistance);
// The same sum over `lights` (every one evaluated).
VplIrradiance vplIrradianceSum(std::span<const Vpl> lights, glm::vec3 p, glm::vec3 n,
                               float clampDistance);

}  // namespace bounce
