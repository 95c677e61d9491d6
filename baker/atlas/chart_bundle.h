// Bundles of sub-texel charts. A chart no wider than one texel either way is below the
// lightmap's resolution, yet on its own it costs its texel plus the padding around it: 9 texels
// with 2 texels of padding. Its texel holds one value for the whole piece anyway, so pieces
// that lie within one texel of each other and face the same way may share texels, which is all
// a bundle does. Internal to the atlas.
#pragma once

#include <vector>

#include "atlas/chart.h"

namespace bounce {

// Charts (in metres, oriented, lower corner at 0) no wider than `texelSize` metres both ways,
// whose area-weighted centres fall in one world-space cube of side `texelSize` (cubes on the
// grid of multiples of texelSize) and whose mean normals point to the same of the six axis
// directions, become one ChartSource::Bundle chart: the pieces side by side in shelf rows, each
// moved rigidly (no piece overlaps another; the density of each is kept). So a bundle's texels
// average light over at most one texel's cube of space and one sixth of the directions. A
// bundle stands where its first piece stood; charts that bundle with nothing are kept as they
// are; Degenerate charts never bundle. Deterministic: groups and rows in chart order.
std::vector<Chart> bundleSubTexelCharts(const WorldMesh& mesh, std::vector<Chart> charts,
                                        float texelSize);

}  // namespace bounce
