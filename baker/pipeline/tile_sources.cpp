#include "pipeline/tile_sources.h"

#include <filesystem>

#include "pipeline/scene_bake.h"
#include "pipeline/tile_journal.h"

namespace bounce {

TileSources::TileSources() = default;
TileSources::TileSources(TileSources&&) noexcept = default;
TileSources::~TileSources() = default;

TileSources openTileSources(const SceneBakeSettings& o, const nlohmann::json& key,
                            std::vector<std::string>& notes) {
  TileSources sources;
  LightmapTiles& tiles = sources.tiles;
  tiles.size = o.tileSize;
  tiles.shard = o.shard;
  tiles.shards = o.shards;
  tiles.exchange = o.exchange;
  const auto restore = [&](TileJournal&& journal) {
    for (TileRecord& record : journal.records) tiles.restored.push_back(std::move(record));
  };
  for (const std::filesystem::path& part : o.parts) {
    TileJournal journal = readTileJournal(part);
    checkTileJournalKey(part, journal.key, key, kTileKeyNotShared);
    restore(std::move(journal));
  }
  if (!o.parts.empty()) tiles.computeMissing = false;
  if (o.journal.empty()) return sources;
  constexpr const char* kSceneOnly[] = {"scene"};
  if (o.resume && std::filesystem::exists(o.journal)) {
    TileJournal earlier = readTileJournal(o.journal);
    checkTileJournalKey(o.journal, earlier.key, key, kSceneOnly);
    if (earlier.droppedBytes > 0)
      notes.push_back(o.journal.string() + ": its last " + std::to_string(earlier.droppedBytes) +
                      " bytes were a tile cut short when the bake stopped: dropped");
    sources.journal = std::make_unique<TileJournalWriter>(o.journal, earlier);
    restore(std::move(earlier));
  } else {
    sources.journal = std::make_unique<TileJournalWriter>(o.journal, key);
  }
  tiles.finished = [&writer = *sources.journal](const TileRecord& record) {
    writer.append(record);
  };
  return sources;
}

}  // namespace bounce
