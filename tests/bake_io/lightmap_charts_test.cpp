// Charts recovered from corner UVs, and the chart image the renderer's chart view samples.
#include <gtest/gtest.h>

#include "bake_folder/lightmap_charts.h"

using namespace bounce;

namespace {

// Region 0: a quad of two triangles sharing the atlas edge (0.25,0.25)-(0.5,0.5), plus a lone
// triangle elsewhere; region 1: one triangle whose corners coincide with the quad's in 3D but
// not in the atlas (a seam).
LightmapLayout twoRegions() {
  LightmapLayout l;
  l.width = 8;
  l.height = 4;
  l.texelSize = 0.1f;
  l.instances = {
      {0,
       {{0.25f, 0.25f},
        {0.5f, 0.25f},
        {0.5f, 0.5f},  // quad, first half
        {0.25f, 0.25f},
        {0.5f, 0.5f},
        {0.25f, 0.5f},  // quad, second half (shared edge)
        {0.625f, 0.5f},
        {0.875f, 0.5f},
        {0.625f, 0.875f}}},  // a chart of its own
      {2, {{0.0f, 0.0f}, {0.125f, 0.0f}, {0.0f, 0.25f}}},
  };
  return l;
}

}  // namespace

TEST(LightmapCharts, TrianglesSharingAnAtlasEdgeShareAChart) {
  const LightmapCharts charts = findCharts(twoRegions());
  EXPECT_EQ(charts.count, 3);
  ASSERT_EQ(charts.triangleChart.size(), 2u);
  EXPECT_EQ(charts.triangleChart[0], (std::vector<uint32_t>{0, 0, 1}));
  EXPECT_EQ(charts.triangleChart[1], (std::vector<uint32_t>{2}));
}

TEST(LightmapCharts, ChartImageColoursEveryOverlappedTexelAndNothingElse) {
  const LightmapLayout layout = twoRegions();
  const Image image = chartImage(layout, findCharts(layout));
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 4);
  // The quad covers texels x 2..3, y 1 exactly (u 0.25..0.5, v 0.25..0.5 of 8×4), and touches
  // its neighbours on their borders (conservative).
  EXPECT_EQ(image.at(2, 1), chartColour(0));
  EXPECT_EQ(image.at(3, 1), chartColour(0));
  // The lone triangle, in texels (5,2) (7,2) (5,3.5): its hypotenuse 1.5x + 2y = 14.5 passes
  // below texel (6,3)'s corner (1.5·6 + 2·3 = 15) and above texel (6,2)'s (13).
  EXPECT_EQ(image.at(6, 2), chartColour(1));
  EXPECT_EQ(image.at(5, 3), chartColour(1));
  EXPECT_EQ(image.at(6, 3), glm::vec3(0.0f));
  EXPECT_EQ(image.at(0, 0), chartColour(2));
  EXPECT_EQ(image.at(5, 0), glm::vec3(0.0f));
  EXPECT_NE(chartColour(0), chartColour(1));
  EXPECT_GT(glm::length(chartColour(7)), 0.1f);
}
