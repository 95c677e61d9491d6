// The tile scheduler: how a tiled stage's tiles are distributed, in one place. The bake's tiled
// stages (the irradiance and the static area lights' visibility, tile_grid.h) each hand it three
// calls: compute a list of tiles, encode one tile's texels as bytes, decode bytes into the whole
// map (tile_payload.h). It does the rest, alike for every stage:
//   restore   tiles earlier runs finished (a journal, the shards' parts) are decoded, not computed
//   to-do     this bake's share (every tile, or one shard's) less the restored, costliest first
//   journal   each tile computed here goes to LightmapTiles::finished (the journal) as bytes
//   share     with an exchange (tile_exchange.h) the to-do tiles are pulled from its queue
//   receive   the tiles other processes computed come back through the exchange (the keeper's)
// A tile's bytes are its texels bit for bit, so the map is the same whichever way each tile came.
// GL-free.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "bake/tile_grid.h"
#include "bake/tile_record.h"
#include "bake/tile_work.h"
#include "trace/stage_progress.h"

namespace bounce {

class TileExchange;

// How the texel stages' tiles are shared out (tile_grid.h). The defaults compute every tile.
struct LightmapTiles {
  int size = kDefaultTileSize;  // texels on a side
  int shard = 0, shards = 1;    // compute only shard `shard` (0-based) of `shards`'s tiles
  // Finished tiles of earlier runs (a journal, or every shard's): restored, not computed. A
  // tile that is not the bake's, or bytes that do not fit it, throw LoadError naming the source.
  std::vector<TileRecord> restored;
  // false: a tile this bake would have to compute is an error (a merge, which only gathers).
  bool computeMissing = true;
  // Told of each tile computed here, with its bytes, from the worker that finished it (several
  // at once: it must lock what it shares); may be empty.
  std::function<void(const TileRecord&)> finished;
  // Tiles shared out among processes as they bake (tile_exchange.h); null: none. A process that
  // is not the keeper stops after the tile stages, like a shard.
  TileExchange* exchange = nullptr;
};

// Thrown when a bake that may not compute (LightmapTiles::computeMissing false) lacks tiles.
struct MissingTiles : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A tiled stage as three calls; Texels is its whole-map result (TexelIrradiance,
// VisibilityTexels).
template <class Texels>
struct TiledStage {
  TileStage stage = TileStage::Irradiance;
  // Computes `work`'s tiles, counting their rows on `progress` (may be null), and calls
  // done(tile, texels) from the worker that finished each; the other tiles' texels stay zero.
  std::function<Texels(const TileWork& work, StageProgress* progress,
                       std::function<void(uint32_t tile, const Texels& texels)> done)>
      compute;
  // One tile's texels as bytes.
  std::function<std::vector<unsigned char>(const Texels& texels, TileRect tile)> encode;
  // A tile's bytes into the whole map; throws LoadError naming record.source when they do not
  // fit the tile.
  std::function<void(const TileRecord& record, TileRect tile, Texels& into)> decode;
};

// Begins a stage's progress with the rows of texels it will compute; may return null.
using BeginTileStage = std::function<std::unique_ptr<StageProgress>(uint64_t rows)>;

class TileScheduler {
 public:
  // `byCost`: the tiles with work, costliest first (tilesByCost). Throws LoadError for a
  // restored tile that is not one of them, or one held twice with different bytes.
  TileScheduler(const TileGrid& grid, std::vector<uint32_t> byCost, const LightmapTiles& tiles);

  uint32_t tiles() const { return static_cast<uint32_t>(byCost_.size()); }  // with work
  uint32_t share() const { return static_cast<uint32_t>(mine_.size()); }    // this bake's
  // Only part of the bake is computed here (a shard, or a process of an exchange that is not
  // its keeper): the stages after the tiles do not run.
  bool partial() const;
  // The tiles of `stage`'s share that were restored rather than computed (once it ran).
  uint32_t restored(TileStage stage) const { return restoredCount_[index(stage)]; }

  // Runs `stage`: the to-do tiles computed (begun on begin(rows) after the to-do is known), the
  // restored and received ones decoded into the result.
  template <class Texels>
  Texels run(const TiledStage<Texels>& stage, const BeginTileStage& begin);

 private:
  static std::size_t index(TileStage stage) { return static_cast<std::size_t>(stage) - 1; }
  // The share's tiles of `stage` no earlier run finished; with an exchange, pulled from it.
  TileWork todo(TileStage stage);
  void share(TileStage stage, TileWork& work) const;
  // A tile computed here: to the exchange and the journal.
  void finished(TileStage stage, uint32_t tile, std::vector<unsigned char> bytes) const;
  // The tiles other processes computed (the keeper's), checked and journalled.
  std::vector<TileRecord> received(TileStage stage) const;

  const TileGrid& grid_;
  const LightmapTiles& tiles_;
  std::vector<uint32_t> byCost_, mine_;
  std::vector<uint8_t> hasWork_;                            // by tile
  std::array<std::vector<const TileRecord*>, 2> restored_;  // by stage, then tile
  std::array<uint32_t, 2> restoredCount_{};
};

template <class Texels>
Texels TileScheduler::run(const TiledStage<Texels>& stage, const BeginTileStage& begin) {
  TileWork work = todo(stage.stage);
  const std::unique_ptr<StageProgress> progress = begin(tileRows(work, 0));
  share(stage.stage, work);
  Texels texels = stage.compute(work, progress.get(), [&](uint32_t tile, const Texels& out) {
    finished(stage.stage, tile, stage.encode(out, grid_.rect(tile)));
  });
  for (const TileRecord* record : restored_[index(stage.stage)])
    if (record) stage.decode(*record, grid_.rect(record->tile), texels);
  for (const TileRecord& record : received(stage.stage)) {
    stage.decode(record, grid_.rect(record.tile), texels);
    if (progress) progress->advance(static_cast<uint64_t>(grid_.rect(record.tile).height()));
  }
  return texels;
}

}  // namespace bounce
