// Merging of tiny charts across folds. A chart of a few texels costs its padding many times its
// own area (one covered texel takes 3 × 3 with 2 texels of padding); joined with a small
// neighbour into one conformal map, the padding is paid once. Only small charts merge, so the
// light of large faces never blends across a fold. Internal to the atlas.
#pragma once

#include <vector>

#include "atlas/chart.h"
#include "atlas/chart_flatten.h"
#include "atlas/chart_segment.h"

namespace bounce {

struct FlatGroup {
  std::vector<uint32_t> triangles;
  FlatChart flat;  // metres (texelSize 1); empty when no flattening was acceptable
};

// Smallest first, a chart under `smallArea` m² joins the neighbour (also under 8 × smallArea)
// it shares the longest edge with, when the conformal map of both together has no flipped or
// overlapping triangle and every triangle's area scale lies within [1/3, 3] of the chart's.
// `contacts` index `groups`; charts with an empty flattening take no part. Order is kept.
std::vector<FlatGroup> mergeSmallCharts(const WorldMesh& mesh, std::vector<FlatGroup> groups,
                                        const std::vector<ChartContact>& contacts,
                                        double smallArea);

}  // namespace bounce
