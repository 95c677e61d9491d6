// Packing by texel mask: places charts so that no texel of one lies within `padding` texels
// (Chebyshev distance) of a texel of another, each chart as laid out or turned by 90°, in the
// smallest atlas found. Charts interlock where their bounding rectangles would not. Internal to
// the atlas.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "atlas/chart_mask.h"

namespace bounce {

struct MaskPacking {
  int width = 0, height = 0;       // texels
  std::vector<glm::ivec2> origin;  // atlas texel of each chart's mask texel (0, 0)
  std::vector<int> turn;           // which of chart c's masks was placed
};

// turns[c] are chart c's masks in each orientation the caller offers (as laid out, turned by
// 90°, …: the caller turns, the packer only chooses; turns[c][0] is the chart as laid out). Every
// chart's texels stay padding/2 texels from the atlas's lower and left edges and padding -
// padding/2 from its upper and right ones, as the rectangle packer keeps them. Largest first, each
// at the lowest then leftmost free position of the orientation whose top is lowest, for a few atlas
// widths (packed in parallel, the same atlas whatever the threads); the smallest width × height
// wins. Nothing when the charts do not fit in maxSize × maxSize.
std::optional<MaskPacking> packMasks(const std::vector<std::vector<ChartMask>>& turns, int padding,
                                     int maxSize);

}  // namespace bounce
