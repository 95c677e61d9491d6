#include "atlas/chart_mask.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "atlas/uv_geometry.h"

namespace bounce {

ChartMask emptyMask(glm::ivec2 cells) {
  ChartMask mask;
  mask.width = cells.x;
  mask.height = cells.y;
  mask.words = (cells.x + 63) / 64;
  mask.bits.assign(static_cast<std::size_t>(mask.words) * cells.y, 0);
  return mask;
}

ChartMask rasteriseChart(const std::vector<glm::vec2>& cornerUv, glm::ivec2 cells) {
  ChartMask mask = emptyMask(cells);
  constexpr float epsilon = 0.5f * kCoverageEpsilon;
  bool any = false;
  for (std::size_t k = 0; k + 2 < cornerUv.size(); k += 3) {
    const glm::vec2 a = cornerUv[k], b = cornerUv[k + 1], c = cornerUv[k + 2];
    const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
    const int x1 = std::min(cells.x - 1, static_cast<int>(std::floor(hi.x)));
    const int y1 = std::min(cells.y - 1, static_cast<int>(std::floor(hi.y)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const glm::vec2 cell(static_cast<float>(x), static_cast<float>(y));
        if (triangleOverlapsBox(a, b, c, cell + epsilon, cell + (1.0f - epsilon))) {
          mask.set(x, y);
          any = true;
        }
      }
  }
  if (!any)
    for (int y = 0; y < cells.y; ++y)
      for (int x = 0; x < cells.x; ++x) mask.set(x, y);
  return mask;
}

ChartMask dilateMask(const ChartMask& mask, int radius) {
  ChartMask grown = emptyMask({mask.width + 2 * radius, mask.height + 2 * radius});
  // Rows first (each set texel spreads over 2·radius + 1 columns), then columns.
  ChartMask wide = emptyMask({grown.width, mask.height});
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (mask.at(x, y))
        for (int d = 0; d <= 2 * radius; ++d) wide.set(x + d, y);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < wide.width; ++x)
      if (wide.at(x, y))
        for (int d = 0; d <= 2 * radius; ++d) grown.set(x, y + d);
  return grown;
}

std::size_t setTexels(const ChartMask& mask) {
  std::size_t count = 0;
  for (const uint64_t word : mask.bits) count += static_cast<std::size_t>(std::popcount(word));
  return count;
}

}  // namespace bounce
