// The charts of a lightmap layout, recovered from its corner UVs alone, and an atlas-sized image
// of them (for the renderer's chart/texel-density view and for seam measurements). GL-free.
//
// Two triangles of one instance lie in one chart when they share an edge whose two corners have
// the same atlas UVs (bit for bit): inside a chart the flattening is continuous, and charts are
// packed with padding, so triangles of different charts never share an atlas edge.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/lightmap_layout.h"
#include "image/image.h"

namespace bounce {

struct LightmapCharts {
  int count = 0;  // charts over the whole layout, numbered 0..count-1
  // triangleChart[r][t]: chart of triangle t of layout.instances[r].
  std::vector<std::vector<uint32_t>> triangleChart;
};

LightmapCharts findCharts(const LightmapLayout& layout);

// A distinct, fully saturated-ish colour for chart `chart` (deterministic, never black).
glm::vec3 chartColour(uint32_t chart);

// layout.width × layout.height, rows top first: the chart of every texel a triangle overlaps
// (conservatively, as below), −1 where none does.
std::vector<int32_t> chartIdImage(const LightmapLayout& layout, const LightmapCharts& charts);

// layout.width × layout.height, rows top first: every texel a triangle overlaps (conservatively:
// any overlap of the texel's square with the triangle's UV triangle) holds its chart's colour,
// uncovered texels are black.
Image chartImage(const LightmapLayout& layout, const LightmapCharts& charts);

}  // namespace bounce
