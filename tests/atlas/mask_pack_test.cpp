// Packing by texel mask (baker/atlas/mask_pack.h): charts interlock where their padded bounding
// rectangles could not, and no texel of one chart comes within `padding` texels (Chebyshev
// distance) of another's, nor closer to the atlas's edges than the rectangle packer keeps them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <tbb/task_arena.h>

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

// Texels of different charts more than `padding` apart (Chebyshev) and inside the edge margins,
// checked on a grid of owners: each texel looks at its (2·padding + 1)² square.
void expectPaddingKept(const std::vector<std::vector<ChartMask>>& turns, const MaskPacking& packing,
                       int padding) {
  const int lo = padding / 2, hi = padding - padding / 2;
  std::vector<int> owner(static_cast<std::size_t>(packing.width) * packing.height, -1);
  const std::vector<PlacedTexel> texels = placedTexels(turns, packing);
  for (const PlacedTexel& t : texels) {
    ASSERT_TRUE(t.x >= lo && t.y >= lo && t.x < packing.width - hi && t.y < packing.height - hi)
        << "texel (" << t.x << ", " << t.y << ") of chart " << t.chart << " outside the margins";
    owner[static_cast<std::size_t>(t.y) * packing.width + t.x] = t.chart;
  }
  for (const PlacedTexel& t : texels)
    for (int y = std::max(0, t.y - padding); y <= std::min(packing.height - 1, t.y + padding); ++y)
      for (int x = std::max(0, t.x - padding); x <= std::min(packing.width - 1, t.x + padding);
           ++x) {
        const int other = owner[static_cast<std::size_t>(y) * packing.width + x];
        ASSERT_TRUE(other < 0 || other == t.chart)
            << "texel (" << t.x << ", " << t.y << ") of chart " << t.chart << " is within "
            << padding << " texels of texel (" << x << ", " << y << ") of chart " << other;
      }
}

// Hundreds of charts, many of the same shape (the packer resumes an equal mask's search where
// the last one stopped) and many small ones for the holes, packed on one thread and on several.
TEST(MaskPack, ManyChartsKeepThePaddingAndTheSameAtlasWhateverTheThreads) {
  std::vector<std::vector<ChartMask>> turns;
  uint32_t seed = 12345u;
  const auto next = [&](int n) {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<int>((seed >> 8) % static_cast<uint32_t>(n));
  };
  for (int i = 0; i < 300; ++i) {
    const float side = static_cast<float>(1 + next(i % 3 == 0 ? 24 : 6));
    const float arm = std::min(side, static_cast<float>(1 + next(3)));
    const glm::ivec2 cells(static_cast<int>(side), static_cast<int>(side));
    if (next(2) == 0) {
      turns.push_back(turnsOf(lShape(side, arm), cells));
    } else {  // a strip `arm` texels wide from corner to corner of its square
      const std::vector<glm::vec2> strip = {{0.0f, 0.0f}, {arm, 0.0f},        {side, side - arm},
                                            {0.0f, 0.0f}, {side, side - arm}, {side - arm, side}};
      turns.push_back(turnsOf(strip, cells));
    }
  }
  for (const int padding : {1, 2, 3}) {
    std::optional<MaskPacking> alone, shared;
    tbb::task_arena(1).execute([&] { alone = packMasks(turns, padding, 4096); });
    tbb::task_arena(2).execute([&] { shared = packMasks(turns, padding, 4096); });
    ASSERT_TRUE(alone && shared);
    EXPECT_EQ(alone->width, shared->width);
    EXPECT_EQ(alone->height, shared->height);
    EXPECT_EQ(alone->origin, shared->origin);
    EXPECT_EQ(alone->turn, shared->turn);
    expectPaddingKept(turns, *alone, padding);
  }
}

}  // namespace
}  // namespace bounce::test
