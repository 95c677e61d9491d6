#include "bake/tile_scheduler.h"

#include <string>

#include "bake/tile_exchange.h"
#include "io/load_error.h"

namespace bounce {

TileScheduler::TileScheduler(const TileGrid& grid, std::vector<uint32_t> byCost,
                             const LightmapTiles& tiles)
    : grid_(grid),
      tiles_(tiles),
      byCost_(std::move(byCost)),
      mine_(tiles.shards > 1 ? shardTiles(byCost_, tiles.shard, tiles.shards) : byCost_) {
  hasWork_.assign(grid.count(), 0);
  for (const uint32_t t : byCost_) hasWork_[t] = 1;
  for (std::vector<const TileRecord*>& r : restored_) r.assign(grid.count(), nullptr);
  for (const TileRecord& record : tiles.restored) {
    if (record.tile >= grid.count() || !hasWork_[record.tile])
      throw LoadError(record.source, "holds tile " + std::to_string(record.tile) +
                                         ", which is not one of this bake's " +
                                         std::to_string(byCost_.size()) + " tiles with work");
    const TileRecord*& slot = restored_[index(record.stage)][record.tile];
    if (slot && slot->bytes != record.bytes)
      throw LoadError(record.source, "holds tile " + std::to_string(record.tile) + " twice, " +
                                         "with different texels (also in " + slot->source.string() +
                                         ")");
    slot = &record;
  }
}

bool TileScheduler::partial() const {
  return tiles_.shards > 1 || (tiles_.exchange && !tiles_.exchange->keeper());
}

TileWork TileScheduler::todo(TileStage stage) {
  TileWork work{&grid_, {}, {}};
  for (const uint32_t t : mine_)
    if (!restored_[index(stage)][t]) work.tiles.push_back(t);
  if (!work.tiles.empty() && !tiles_.computeMissing)
    throw MissingTiles(std::to_string(work.tiles.size()) + " of the " +
                       std::to_string(mine_.size()) + " tiles of the " + tileStageName(stage) +
                       " are in no part (tile " + std::to_string(work.tiles.front()) + " first)");
  restoredCount_[index(stage)] = static_cast<uint32_t>(mine_.size() - work.tiles.size());
  return work;
}

void TileScheduler::share(TileStage stage, TileWork& work) const {
  TileExchange* exchange = tiles_.exchange;
  if (!exchange) return;
  exchange->open(stage, work.tiles);
  work.next = [exchange, stage] { return exchange->next(stage); };
}

void TileScheduler::finished(TileStage stage, uint32_t tile,
                             std::vector<unsigned char> bytes) const {
  const TileRecord record{stage, tile, std::move(bytes), {}};
  if (tiles_.exchange) tiles_.exchange->finished(record);
  if (tiles_.finished) tiles_.finished(record);
}

std::vector<TileRecord> TileScheduler::received(TileStage stage) const {
  std::vector<TileRecord> records;
  if (tiles_.exchange) records = tiles_.exchange->gather(stage);
  for (const TileRecord& record : records) {
    if (record.tile >= grid_.count() || !hasWork_[record.tile])
      throw std::runtime_error("a process sent tile " + std::to_string(record.tile) +
                               ", which is not one of this bake's tiles");
    if (tiles_.finished) tiles_.finished(record);
  }
  return records;
}

}  // namespace bounce
