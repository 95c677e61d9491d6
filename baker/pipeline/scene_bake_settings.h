// What a scene bake is asked to do (bounce-bake's options, with its defaults: docs/baker.md), and
// its inputs as JSON: the part of the settings a bake's bytes depend on, which a tile journal's
// key and a shard's part carry so that a resume or a merge bakes with the same ones. GL-free.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/tile_exchange.h"
#include "bake/tile_grid.h"
#include "ray/ray_kernel.h"
#include "trace/trace_settings.h"

namespace bounce {

struct SceneBakeSettings {
  float texelSize = 0.0f;  // m; 0: the density rule (atlas/texel_density.h)
  int texelBudget = 0;     // texels instead of the rule; 0: the rule
  int64_t maxTexels;       // cap (texel_density.h's default)
  int spp;                 // most samples per texel
  float targetError;       // relative standard error to stop a texel at; 0: always spp
  int maxDepth;
  uint32_t seed = 0;
  // Next-event estimation's pick (trace/trace_settings.h). Bake inputs without it (journals of
  // bakes before it existed) mean ByPower, the only pick then.
  LightChoice lightChoice = LightChoice::ByPlace;
  int threads = 0;  // 0: all cores
  RayBackend backend = RayBackend::Embree;
  bool denoise;
  int vpls;        // most VPLs; 0: none
  float vplError;  // relative standard error of the total VPL flux to stop at
  // Bytes the bake may take at its peak (bake_memory.h's estimate, after the atlas); 0: no limit.
  double maxMemory = 0.0;
  int tileSize = kDefaultTileSize;  // texels on a side of the texel stages' tiles (tile_grid.h)

  // Where the tiles go and come from (pipeline/tile_journal.h).
  std::filesystem::path journal;  // each finished tile is appended here; empty: nowhere
  bool resume = false;            // restore the tiles `journal` holds (its key must match)
  int shard = 0, shards = 1;      // bake only shard `shard` (0-based) of `shards`'s tiles
  // A merge: every tile comes from these shards' journals; none is computed.
  std::vector<std::filesystem::path> parts;
  // Tiles shared out among processes as they bake (bake/tile_exchange.h, bounce-bake --mpi);
  // null: none. A process that is not the keeper bakes its tiles only (SceneBake::partial).
  TileExchange* exchange = nullptr;
  SceneBakeSettings();
};

// The inputs a bake's bytes depend on: everything above but threads, maxMemory and the tiles'
// whereabouts.
nlohmann::json bakeInputsJson(const SceneBakeSettings& settings);
// Inverse of bakeInputsJson on top of `base` (threads and the rest kept); throws
// std::runtime_error naming the field that is missing or of the wrong type.
SceneBakeSettings bakeSettingsFromInputs(const nlohmann::json& inputs, SceneBakeSettings base);

}  // namespace bounce
