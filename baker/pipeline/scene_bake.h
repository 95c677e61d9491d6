// The bake of a whole scene as one library call: bakeScene runs the numbered stages (atlas, ray
// kernel, texel coverage, leak guard, irradiance, light visibility, filters, VPLs, probes), reports
// each to a BakeObserver that can cancel (trace/stage_progress.h), and returns the bake folder's
// contents with its manifest, ready for writeBake. Nothing is written here: a cancelled or
// failed bake leaves no file. bounce-bake, the tests, the benchmarks and the viewer's re-bake
// call it. GL-free.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "bake_folder/bake_folder.h"
#include "pipeline/scene_bake_settings.h"
#include "trace/stage_progress.h"

namespace bounce {

struct Scene;

// The estimate said the bake would go over SceneBakeSettings::maxMemory; nothing was baked.
struct BakeOverMemoryBudget : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SceneBake {
  Bake folder;                     // layout, lightmap, error map, VPLs, visibility and the manifest
  std::vector<std::string> notes;  // the atlas's (e.g. the texel cap) and the visibility's
  uint64_t coveredTexels = 0;
  double estimatedPeakBytes = 0.0;  // bake_memory.h, made after the atlas
  double measuredPeakBytes = 0.0;   // the process's peak resident set at the end
  // The tiles with work, and how many were restored from a journal or parts, not computed.
  uint32_t tiles = 0, tilesRestored = 0;
  // A shard (settings.shards > 1): only its tiles were baked, into settings.journal; `folder`
  // and `manifest` are empty (bounce-bake merge makes the folder from every shard's tiles).
  bool partial = false;
};

// The key of this bake's tile journal (pipeline/tile_journal.h): everything a tile's bytes
// depend on (formats, scene hash, the inputs, the atlas's size) and, apart from that, the scene
// file and the shard, which a resume checks and a merge does not (kTileKeyNotShared).
nlohmann::json tileJournalKey(const Scene& scene, const SceneBakeSettings& settings, int atlasWidth,
                              int atlasHeight);
inline constexpr const char* kTileKeyNotShared[] = {"scene", "shard"};

// The stages bakeScene will run for this scene and settings, in order (its StagePlan).
std::vector<std::string> sceneBakeStages(const Scene& scene, const SceneBakeSettings& settings);

// Throws BakeCancelled when `observer` cancels, std::runtime_error for a scene with nothing
// static to bake, LoadError for a journal or part that is not this bake's, MissingTiles for a
// merge that lacks tiles. `observer` may be null. With settings.journal, every tile finished
// is appended there (after the restored ones when settings.resume); the caller removes the
// journal once the folder is written.
SceneBake bakeScene(const Scene& scene, const SceneBakeSettings& settings,
                    BakeObserver* observer = nullptr);

}  // namespace bounce
