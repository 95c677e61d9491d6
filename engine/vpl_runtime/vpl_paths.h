// The VPLs of a prefix of a VPL set's light paths: what the viewer draws when asked for fewer
// VPLs than the bake holds. GL-free.
//
// A bake's N light paths each carry flux β/N (docs/vpl.md: the particles (y_k, β_k/N) estimate
// the flux arriving at the surfaces); the first P of them, each VPL's flux × N/P, are the same
// estimator over P paths: unbiased, noisier, with fewer VPLs. P = N gives the set unchanged.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bake_folder/vpl.h"

namespace bounce {

// The light paths of `vpls`: `bakePaths` (bake.json "vpls"."paths") when it is positive, else one
// more than the highest path index (a hand-made set; paths that left no VPL are then not counted).
uint64_t vplPathCount(std::span<const Vpl> vpls, uint64_t bakePaths);

// The VPLs with path < `paths`, in order, their flux × totalPaths/paths; `paths` ≥ totalPaths
// returns the set unchanged, 0 returns none.
std::vector<Vpl> firstPathsVpls(std::span<const Vpl> vpls, uint64_t paths, uint64_t totalPaths);

}  // namespace bounce
