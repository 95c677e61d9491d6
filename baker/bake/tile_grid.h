// The atlas cut into square tiles: the unit of work the irradiance and visibility stages hand
// out, journal (tile_journal.h) and deal to shards.
//
// Tile t covers texels [x0, x1) × [y0, y1) of a `size` × `size` grid laid over the atlas from
// its top-left corner, row by row (the last column and row are narrower). A texel's result never
// depends on its tile: every texel draws from its own sampler pattern (seed, texel), so the
// tiling, the order tiles are done in, the thread count, the shard or the machine change when a
// texel is computed, never its bytes. GL-free.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/tile_record.h"  // kDefaultTileSize

namespace bounce {

struct TexelCoverage;

struct TileRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // texels, [x0, x1) × [y0, y1)
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

class TileGrid {
 public:
  // Throws std::invalid_argument for a size < 1 or an empty atlas.
  TileGrid(int width, int height, int size);
  int size() const { return size_; }
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  uint32_t count() const { return static_cast<uint32_t>(columns_) * static_cast<uint32_t>(rows_); }
  TileRect rect(uint32_t tile) const;

 private:
  int width_, height_, size_, columns_, rows_;
};

// The tiles that hold covered texels (texels with sample points after the leak guard), in the
// order to hand them out: most sample points first (the cost of a tile grows with its points),
// ties by index. Tiles without points have no work and are left out.
std::vector<uint32_t> tilesByCost(const TileGrid& grid, const TexelCoverage& coverage);

// Shard k of n (0-based): the tiles dealt in turn from `byCost`, so every shard gets a like
// share of the costly and the cheap ones.
std::vector<uint32_t> shardTiles(const std::vector<uint32_t>& byCost, int k, int n);

}  // namespace bounce
