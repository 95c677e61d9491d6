#include "bake/tile_grid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "bake/texel_coverage.h"

namespace bounce {

TileGrid::TileGrid(int width, int height, int size) : width_(width), height_(height), size_(size) {
  if (size < 1) throw std::invalid_argument("tile size " + std::to_string(size) + " is below 1");
  if (width < 1 || height < 1)
    throw std::invalid_argument("an empty atlas (" + std::to_string(width) + "x" +
                                std::to_string(height) + ") has no tiles");
  columns_ = (width + size - 1) / size;
  rows_ = (height + size - 1) / size;
}

TileRect TileGrid::rect(uint32_t tile) const {
  const int column = static_cast<int>(tile % static_cast<uint32_t>(columns_));
  const int row = static_cast<int>(tile / static_cast<uint32_t>(columns_));
  TileRect r;
  r.x0 = column * size_;
  r.y0 = row * size_;
  r.x1 = std::min(r.x0 + size_, width_);
  r.y1 = std::min(r.y0 + size_, height_);
  return r;
}

std::vector<uint32_t> tilesByCost(const TileGrid& grid, const TexelCoverage& coverage) {
  std::vector<uint64_t> points(grid.count(), 0);
  for (uint32_t t = 0; t < grid.count(); ++t) {
    const TileRect r = grid.rect(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x)
        points[t] += coverage.pointCount(static_cast<std::size_t>(y) * coverage.width + x);
  }
  std::vector<uint32_t> order;
  for (uint32_t t = 0; t < grid.count(); ++t)
    if (points[t] > 0) order.push_back(t);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return points[a] > points[b]; });
  return order;
}

std::vector<uint32_t> shardTiles(const std::vector<uint32_t>& byCost, int k, int n) {
  if (n < 1 || k < 0 || k >= n)
    throw std::invalid_argument("shard " + std::to_string(k + 1) + " of " + std::to_string(n) +
                                " does not exist");
  std::vector<uint32_t> mine;
  for (std::size_t i = static_cast<std::size_t>(k); i < byCost.size();
       i += static_cast<std::size_t>(n))
    mine.push_back(byCost[i]);
  return mine;
}

}  // namespace bounce
