// Stages 3–7 of the scene bake (scene_bake_stages.h): the lightmap over its tiles.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "atlas/atlas.h"
#include "bake/lightmap_bake.h"
#include "pipeline/scene_bake.h"
#include "pipeline/scene_bake_stages.h"
#include "pipeline/tile_journal.h"
#include "pipeline/tile_sources.h"
#include "scene/static_scene.h"

namespace bounce {

LightmapLayout staticLayout(const Scene& scene, LightmapLayout layout) {
  const std::vector<uint32_t> numbers = staticInstanceNumbers(scene);
  for (InstanceLightmapUv& region : layout.instances) region.instance = numbers.at(region.instance);
  return layout;
}

LightmapBake lightmapStages(const Scene& scene, const StaticGeometry& statics, const Atlas& atlas,
                            const SceneBakeSettings& o, const StagePlan& plan, SceneBake& result) {
  LightmapBakeSettings settings = defaultBakeSettings();
  settings.stages = &plan;
  // The tiles: this bake's share, those a journal or the parts already hold, where new ones go.
  TileSources tiles = openTileSources(
      o, tileJournalKey(scene, o, atlas.layout.width, atlas.layout.height), result.notes);
  settings.tiles = std::move(tiles.tiles);
  settings.irradiance.maxSpp = o.maxSpp;
  settings.irradiance.targetError = o.targetError;
  settings.irradiance.maxDepth = o.maxDepth;
  settings.irradiance.seed = o.seed;
  settings.irradiance.lightChoice = o.lightChoice;
  settings.irradiance.threads = o.threads;
  settings.denoise = o.denoise;
  settings.gather = o.gather;
  settings.cacheSpp = o.cacheSpp;
  settings.errorFloor = o.errorFloor;
  settings.pointsPerTexel = o.pointsPerTexel;
  LightmapBake bake = bakeLightmap(*statics.scene, *statics.geometry, *statics.kernel,
                                   staticLayout(scene, atlas.layout), settings);
  result.tiles = bake.tiles;
  result.tilesRestored = bake.tilesRestored;
  if (o.resume && bake.tilesRestored > 0)
    result.notes.push_back("resumed: " + std::to_string(bake.tilesRestored) + " of " +
                           std::to_string(bake.tilesShare) + " tiles were in " +
                           o.journal.string());
  if (bake.errorFloorIrradiance > 0.0) {
    char floor[96];
    std::snprintf(floor, sizeof floor, "%.3g W/m^2 (%.3g x the cache's mean %.3g W/m^2)",
                  bake.errorFloorIrradiance, static_cast<double>(o.errorFloor),
                  bake.cacheMeanIrradiance);
    result.notes.push_back(std::string("texels dimmer than ") + floor +
                           " stopped at the target times that floor");
  }
  if (!bake.partial && !bake.irradiance.allFinite())
    throw std::runtime_error("the lightmap has non-finite texels (a bug: please report)");
  return bake;
}

}  // namespace bounce
