// Reduction of a VPL set to at most K runtime VPLs (optional clustering), keeping
// the total flux per channel: each cluster becomes one VPL whose flux is the sum of its members'
// (in double, rounded once), at its members' flux-weighted centroid (luminance weights, so the
// first-order term of the far field, the "dipole", vanishes), with the normalised flux-weighted
// mean normal. Clusters never mix normals of different dominant axis or sign (a floor VPL and a
// wall VPL at a corner stay apart), then the cluster with the largest luminance(Φ)·extent² is
// split at the flux-weighted median of its longest axis, until there are K clusters or none can
// be split. Deterministic (no threads; ties broken by index). GL-free; the baker and the
// renderer's VPL groups (vpl_runtime/vpl_groups.h) share it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "bake_folder/vpl.h"

namespace bounce {

// k ≥ vpls.size(): the set unchanged. k < 6 may return more than k when the normals fall into
// more than k dominant-axis groups (groups are never merged).
std::vector<Vpl> reduceVpls(std::span<const Vpl> vpls, std::size_t k);

// The clusters themselves: indices into `vpls`, each cluster non-empty, every index once.
// reduceVpls(vpls, k)[c] == mergeVpls(vpls, groupVpls(vpls, k)[c]) (for k < vpls.size()).
std::vector<std::vector<uint32_t>> groupVpls(std::span<const Vpl> vpls, std::size_t k);
// One VPL standing for `members`: Σ flux (double, rounded once), luminance-weighted centroid,
// normalised flux-weighted mean normal.
Vpl mergeVpls(std::span<const Vpl> vpls, std::span<const uint32_t> members);

}  // namespace bounce
