// What a scene bake is asked to do (bounce-bake's options, with its defaults: docs/baker.md), in
// two parts: what its bytes depend on (BakeSettings, bake_folder/bake_settings.h: the one schema
// bake.json and the tile journal's key share) and how its work is distributed (BakeWork: no byte
// of the folder depends on it). GL-free.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "bake/tile_record.h"
#include "bake_folder/bake_settings.h"

namespace bounce {

class TileExchange;
enum class RayBackend : uint8_t;  // ray/ray_kernel.h

// How the work is distributed: threads, memory, tiles and their whereabouts
// (pipeline/tile_sources.h, bake/tile_scheduler.h).
struct BakeWork {
  int threads = 0;  // 0: all cores
  // Bytes the bake may take at its peak (bake_memory.h's estimate, after the atlas); 0: no limit.
  double maxMemory = 0.0;
  // Texels on a side of the texel stages' tiles (tile_grid.h). No byte depends on it, but a
  // journal's tiles are numbered in it: the journal's key holds it.
  int tileSize = kDefaultTileSize;
  std::filesystem::path journal;  // each finished tile is appended here; empty: nowhere
  bool resume = false;            // restore the tiles `journal` holds (its key must match)
  int shard = 0, shards = 1;      // bake only shard `shard` (0-based) of `shards`'s tiles
  // A merge: every tile comes from these shards' journals; none is computed.
  std::vector<std::filesystem::path> parts;
  // Tiles shared out among processes as they bake (bake/tile_exchange.h, bounce-bake --mpi);
  // null: none. A process that is not the keeper bakes its tiles only (SceneBake::partial).
  TileExchange* exchange = nullptr;
};

struct SceneBakeSettings : BakeSettings, BakeWork {
  // The ray kernel. The bytes depend on it (its hits differ in the last bits), but bake.json
  // names it under "rays", not "settings"; the journal's key holds it.
  RayBackend backend;   // Embree by default
  SceneBakeSettings();  // bounce-bake's defaults
};

// A tile journal's key's settings part (tile_journal.h): bakeSettingsJson with the backend and
// the tile size.
nlohmann::json bakeInputsJson(const SceneBakeSettings& settings);
// Inverse of bakeInputsJson, the BakeWork left at its defaults; throws LoadError(file, ...)
// naming the field that is missing, of the wrong type or out of range.
SceneBakeSettings bakeSettingsFromInputs(const std::filesystem::path& file,
                                         const nlohmann::json& inputs);

}  // namespace bounce
