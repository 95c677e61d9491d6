// Where a scene bake's tiles come from and go, from its settings: the shards' parts of a merge
// and a resumed journal (tile_journal.h) are read and checked against the bake's key, and the
// journal every finished tile is appended to is opened; the tile scheduler
// (bake/tile_scheduler.h) takes the result. GL-free.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "bake/tile_scheduler.h"

namespace bounce {

class TileJournalWriter;
struct SceneBakeSettings;

struct TileSources {
  LightmapTiles tiles;  // its `finished` appends to `journal`
  std::unique_ptr<TileJournalWriter> journal;
  TileSources();
  TileSources(TileSources&&) noexcept;
  ~TileSources();
};

// Throws LoadError for a part or journal that is not this bake's (its key differs from `key`
// beyond the scene file, and for a part the shard). A resumed journal cut short by a kill adds
// a line to `notes`.
TileSources openTileSources(const SceneBakeSettings& settings, const nlohmann::json& key,
                            std::vector<std::string>& notes);

}  // namespace bounce
