// Merging of small and narrow charts across folds. A chart of a few texels costs its padding many
// times its own area (one covered texel takes 3 × 3 with 2 texels of padding), and so does a strip
// one texel wide (a face of a trim or of a chair's bar: L covered texels take 3 × (L + 2)); joined
// with a neighbour into one conformal map, the padding is paid once. Only small or narrow charts
// merge, so the light of large faces never blends across a fold. Internal to the atlas.
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

struct MergeLimits {
  double smallArea = 0.0;    // m²: a tiny chart is under it (16 texels)
  double texelSize = 0.0;    // m: a narrow chart is at most one texel across
  double narrowFold = 1.75;  // radians (100°): the sharpest fold a narrow chart merges across
  double mediumFold = 1.05;  // radians (60°): the sharpest fold a medium chart merges across
};

// Three rules, smallest chart first; each chart joins the neighbour it shares the longest edge
// with that a rule allows and whose union flattens:
//   tiny: a chart under smallArea joins a neighbour under 8 × smallArea across any fold; every
//     triangle's area scale within [1/3, 3] of the union's;
//   narrow: a chart at most one texel across (a sub-texel face of a trim, a rail, a bar) joins
//     any neighbour across folds up to narrowFold (its texels straddle the fold already), never
//     the back of a thin plate;
//   medium: a chart under 16 × smallArea (256 texels) joins a neighbour across folds up to
//     mediumFold (a curtain's pleats, a curved chair back cut by the segmentation's cone), never
//     across a box's 90° edge;
// narrow and medium merges keep every triangle's area scale within [1/2, 2] of the union's and
// happen only when the union's bounding rectangle, in whole texels plus one on every side, is no
// larger than the two charts' together (the padding shrinks). The union is one conformal map with
// no flipped or overlapping triangle (chart_join.h where the two share several runs of edges).
// `contacts` index `groups`; charts with an empty flattening take no part. Order is kept.
// The pass is serial by definition; it runs as windows of choices made in parallel and carried
// out in order, each the serial pass's own (chart_merge.cpp): the same charts at any thread count.
std::vector<FlatGroup> mergeSmallCharts(const WorldMesh& mesh, std::vector<FlatGroup> groups,
                                        const std::vector<ChartContact>& contacts,
                                        const MergeLimits& limits);

// The sides (metres or texels, as the corners) of the chart's minimum-area bounding rectangle,
// the shorter first.
glm::dvec2 boundingSides(const std::vector<glm::vec2>& cornerUv);

}  // namespace bounce
