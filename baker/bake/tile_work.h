// Which tiles a texel stage computes (tile_grid.h): the irradiance and visibility stages take
// one, so a bake can skip the tiles a journal already holds (pipeline/tile_journal.h) or
// compute only one shard's share; each stage says when a tile is done (its `tileDone`).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "bake/tile_grid.h"
#include "trace/denormals_flushed.h"

namespace bounce {

struct TileWork {
  // Null: every texel, as one tile.
  const TileGrid* grid = nullptr;
  // The tiles to compute, handed out in this order; the other tiles' texels are left as they
  // are (zero). Ignored without a grid.
  std::vector<uint32_t> tiles;
  // Instead of `tiles` when set: asked for the next tile after each one (one tile at a time,
  // its rows in parallel), until it gives none (tile_exchange.h).
  std::function<std::optional<uint32_t>()> next;
};

// Rows of texels in `work`'s tiles: the number a stage's progress counts to.
inline uint64_t tileRows(const TileWork& work, int height) {
  if (!work.grid) return static_cast<uint64_t>(height);
  uint64_t rows = 0;
  for (const uint32_t tile : work.tiles)
    rows += static_cast<uint64_t>(work.grid->rect(tile).height());
  return rows;
}

// Calls texelRow(y, x0, x1) for every row of every tile of `work` (the whole image as one tile
// when it has no grid) on the current task arena's threads, tiles in their order and the rows of
// a tile in parallel, then finished(tile) on the thread that did the tile's last row (not for a
// tile cut short by a cancel). Stops handing out rows once cancelled() is true.
template <class Row, class Finished, class Cancelled>
void forEachTileRow(const TileWork& work, int width, int height, Row texelRow, Finished finished,
                    Cancelled cancelled) {
  const TileGrid image(width, height, std::max(width, height));
  const TileGrid& grid = work.grid ? *work.grid : image;
  const auto doTile = [&](uint32_t tile) {
    const TileRect r = grid.rect(tile);
    std::atomic<bool> complete{true};
    tbb::parallel_for(tbb::blocked_range<int>(r.y0, r.y1, 1),
                      [&](const tbb::blocked_range<int>& rows) {
                        const DenormalsFlushed flushed;
                        for (int y = rows.begin(); y != rows.end(); ++y) {
                          if (cancelled()) {
                            complete = false;
                            return;
                          }
                          texelRow(y, r.x0, r.x1);
                        }
                      });
    if (complete) finished(tile);
  };
  if (work.grid && work.next) {
    while (!cancelled()) {
      const std::optional<uint32_t> tile = work.next();
      if (!tile) break;
      doTile(*tile);
    }
    return;
  }
  const std::vector<uint32_t> one = {0};
  const std::vector<uint32_t>& tiles = work.grid ? work.tiles : one;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) doTile(tiles[i]);
                    });
}

}  // namespace bounce
