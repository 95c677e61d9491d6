// Chart segmentation (chart_segment.h): the components of a mesh (faces joined across uncut
// edges) are segmented apart, in parallel, and their charts numbered as one pass over all faces
// numbers them: by their seeds' place in the order of decreasing area.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include "atlas/chart_segment.h"

namespace bounce {
namespace {

// Five flat squares of sides 0.2, 0.4, 0.6, 0.8 and 1 m, apart, in that order in the mesh: five
// components of two triangles each, one chart each. One pass over the faces seeds the charts
// largest triangle first, so chart k is the square of side 1 − 0.2 k: triangles 8 − 2k, 9 − 2k.
// In a 1- and a 4-thread arena.
TEST(ChartSegment, ComponentsAreNumberedAsOnePassOverAllFaces) {
  WorldMesh mesh;
  for (int k = 0; k < 5; ++k) {
    const float side = 0.2f * static_cast<float>(k + 1), x = 2.0f * static_cast<float>(k);
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {{x, 0, 0}, {x + side, 0, 0}, {x + side, side, 0}, {x, side, 0}});
    for (const uint32_t v : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + v);
  }
  for (const int threads : {1, 4}) {
    TriangleGroups groups;
    tbb::task_arena(threads).execute([&] { groups = segmentCharts(mesh, SegmentSettings{}); });
    ASSERT_EQ(groups.charts.size(), 5u) << threads << " threads";
    for (uint32_t k = 0; k < 5; ++k)
      EXPECT_EQ(groups.charts[k], (std::vector<uint32_t>{8 - 2 * k, 9 - 2 * k}))
          << "chart " << k << ", " << threads << " threads";
    EXPECT_TRUE(groups.contacts.empty());
    EXPECT_TRUE(groups.degenerate.empty());
  }
}

}  // namespace
}  // namespace bounce
