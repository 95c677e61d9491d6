// What a bake's bytes depend on, as bounce-bake was asked (its options; their defaults are the
// baker's: pipeline/scene_bake_settings.h), and its one JSON codec. bake.json's "settings" is
// this struct as the bake resolved it (the texel size the atlas chose; a texel budget only where
// no size was given: bake_manifest.h), and a tile journal's key holds it as asked
// (baker/pipeline/tile_journal.h), so a resume or a merge bakes with the same settings. How the
// work is distributed (threads, journal, shards, MPI) is not here: no byte depends on it. GL-free.
//
//   JSON (keys sorted): cacheSpp and gather ("cache"; both only with the cache gather, absent:
//   "paths", the only gather before it existed, so a paths bake keeps its settings hash),
//   denoise, errorFloor (only when > 0, so a bake without keeps its hash), lightChoice ("place" |
//   "power"; absent: "power", the only pick before it existed), maxDepth, maxSpp, maxTexels,
//   pointsPerTexel, seed, targetError (relative standard error), texelBudget, texelSize (m),
//   vplError (relative), vpls. Reals are written as the doubles of the floats the bake used, so a
//   parse gives back the same floats.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "bake_folder/light_choice.h"

namespace bounce {

enum class Gather : uint8_t;  // bake_folder/gather.h

struct BakeSettings {
  float texelSize = 0.0f;    // m; 0: the density rule (baker/atlas/texel_density.h)
  int texelBudget = 0;       // texels instead of the rule; 0: the rule
  int64_t maxTexels = 0;     // cap on the atlas's texels
  int maxSpp = 0;            // most samples per texel
  float targetError = 0.0f;  // relative standard error to stop a texel at; 0: always maxSpp
  int maxDepth = 0;          // most diffuse reflections along a path
  uint32_t seed = 0;
  bool denoise = false;
  LightChoice lightChoice = LightChoice::ByPlace;  // next-event estimation's pick
  int pointsPerTexel = 8;                          // candidate sample points per texel
  int vpls = 0;                                    // most VPLs; 0: none
  float vplError = 0.0f;  // relative standard error of the total VPL flux to stop at
  Gather gather{};        // how texels gather indirect light; Gather::Paths
  int cacheSpp = 0;       // samples per texel of the cache pass (Gather::Cache only)
  // Gather::Cache: a texel dimmer than errorFloor × the cache's mean irradiance stops at
  // targetError × that floor, an absolute error (baker/bake/lightmap_bake.h); 0: none.
  float errorFloor = 0.0f;
};

nlohmann::json bakeSettingsJson(const BakeSettings& settings);

// Reads the settings' fields from `object` (other fields are left alone); throws LoadError(file,
// reason) naming the field (`path` + "." + name) that is missing, of the wrong type or out of
// its range.
BakeSettings parseBakeSettings(const std::filesystem::path& file, const nlohmann::json& object,
                               const std::string& path);

// FNV-1a 64 of bakeSettingsJson's text (bake.json's "settingsHash"), 16 hex digits.
std::string settingsHash(const BakeSettings& settings);
// The same without lightChoice: the hash of bake.json files written before it existed (which
// mean "power").
std::string settingsHashWithoutLightChoice(const BakeSettings& settings);

}  // namespace bounce
