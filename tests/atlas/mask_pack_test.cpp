// Packing by texel mask (baker/atlas/mask_pack.h): charts interlock where their padded bounding
// rectangles could not, and no texel of one chart comes within `padding` texels (Chebyshev
// distance) of another's, nor closer to the atlas's edges than the rectangle packer keeps them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "atlas/chart_mask.h"
#include "atlas/mask_pack.h"

namespace bounce::test {
namespace {

// An L of `side` × `side` texels with arms `arm` texels thick, as 4 triangles (texel units).
std::vector<glm::vec2> lShape(float side, float arm) {
  const auto quad = [](glm::vec2 lo, glm::vec2 hi, std::vector<glm::vec2>& out) {
    for (const glm::vec2 p : {lo, glm::vec2(hi.x, lo.y), hi, lo, hi, glm::vec2(lo.x, hi.y)})
      out.push_back(p);
  };
  std::vector<glm::vec2> corners;
  quad({0.0f, 0.0f}, {side, arm}, corners);
  quad({0.0f, arm}, {arm, side}, corners);
  return corners;
}

// The chart's masks turned by 0°, 90°, 180°, 270° inside its cells.
std::vector<ChartMask> turnsOf(std::vector<glm::vec2> corners, glm::ivec2 cells) {
  std::vector<ChartMask> turns;
  for (int k = 0; k < 4; ++k) {
    turns.push_back(rasteriseChart(corners, cells));
    for (glm::vec2& p : corners) p = {static_cast<float>(cells.y) - p.y, p.x};
    cells = {cells.y, cells.x};
  }
  return turns;
}

struct PlacedTexel {
  int chart, x, y;
};

std::vector<PlacedTexel> placedTexels(const std::vector<std::vector<ChartMask>>& turns,
                                      const MaskPacking& packing) {
  std::vector<PlacedTexel> texels;
  for (std::size_t c = 0; c < turns.size(); ++c) {
    const ChartMask& mask = turns[c][static_cast<std::size_t>(packing.turn[c])];
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x)
        if (mask.at(x, y))
          texels.push_back({static_cast<int>(c), packing.origin[c].x + x, packing.origin[c].y + y});
  }
  return texels;
}

TEST(MaskPack, TwoLShapesInterlockAndKeepThePadding) {
  const int padding = 2;
  const glm::ivec2 cells(12, 12);
  const std::vector<std::vector<ChartMask>> turns = {turnsOf(lShape(12.0f, 2.0f), cells),
                                                     turnsOf(lShape(12.0f, 2.0f), cells)};
  // The rasterised L: 12 + 10 texels in its arms' rows and columns, 44 in all.
  int count = 0;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) count += turns[0][0].at(x, y);
  EXPECT_EQ(count, 44);

  const std::optional<MaskPacking> packing = packMasks(turns, padding, 4096);
  ASSERT_TRUE(packing);
  // Rectangles would need at least 2 × 14 × 14 texels; the Ls nest.
  const int rectangles = 2 * (cells.x + padding) * (cells.y + padding);
  EXPECT_LT(packing->width * packing->height, rectangles)
      << packing->width << " x " << packing->height;

  const std::vector<PlacedTexel> texels = placedTexels(turns, *packing);
  const int lo = padding / 2, hi = padding - padding / 2;
  for (const PlacedTexel& t : texels) {
    EXPECT_GE(t.x, lo);
    EXPECT_GE(t.y, lo);
    EXPECT_LT(t.x, packing->width - hi);
    EXPECT_LT(t.y, packing->height - hi);
    for (const PlacedTexel& u : texels) {
      if (u.chart == t.chart) continue;
      ASSERT_GT(std::max(std::abs(t.x - u.x), std::abs(t.y - u.y)), padding)
          << "texel (" << t.x << ", " << t.y << ") of chart " << t.chart << " and (" << u.x << ", "
          << u.y << ") of chart " << u.chart;
    }
  }
}

TEST(MaskPack, ManyDiagonalStripsKeepThePaddingAndBeatRectangles) {
  const int padding = 2;
  std::vector<std::vector<ChartMask>> turns;
  int rectangles = 0;
  for (int i = 0; i < 12; ++i) {
    const float side = 6.0f + static_cast<float>(i % 5);
    // A strip one texel wide from corner to corner of its square.
    const std::vector<glm::vec2> strip = {{0.0f, 0.0f}, {1.0f, 0.0f},        {side, side - 1.0f},
                                          {0.0f, 0.0f}, {side, side - 1.0f}, {side - 1.0f, side}};
    const glm::ivec2 cells(static_cast<int>(side), static_cast<int>(side));
    turns.push_back(turnsOf(strip, cells));
    rectangles += (cells.x + padding) * (cells.y + padding);
  }
  const std::optional<MaskPacking> packing = packMasks(turns, padding, 4096);
  ASSERT_TRUE(packing);
  EXPECT_LT(packing->width * packing->height, rectangles);
  const std::vector<PlacedTexel> texels = placedTexels(turns, *packing);
  for (const PlacedTexel& t : texels)
    for (const PlacedTexel& u : texels) {
      if (u.chart == t.chart) continue;
      ASSERT_GT(std::max(std::abs(t.x - u.x), std::abs(t.y - u.y)), padding);
    }
}

}  // namespace
}  // namespace bounce::test
