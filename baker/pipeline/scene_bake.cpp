#include "pipeline/scene_bake.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "atlas/atlas.h"
#include "bake/light_visibility_bake.h"
#include "bake/lightmap_bake.h"
#include "bake/tile_exchange.h"
#include "pipeline/bake_memory.h"
#include "pipeline/probe_stage.h"
#include "pipeline/scene_bake_stages.h"
#include "pipeline/tile_journal.h"
#include "scene/area_lights.h"
#include "scene/static_scene.h"
#include "scene/world_geometry.h"
#include "trace/stopwatch.h"

namespace bounce {

StaticGeometry::StaticGeometry() = default;
StaticGeometry::StaticGeometry(StaticGeometry&&) noexcept = default;
StaticGeometry::~StaticGeometry() = default;

// Dynamic instances are left out of the whole bake, lightmap and VPLs alike: they have no
// lightmap region, and where they stand at load time neither shadows nor lights the static
// surfaces' baked light, which therefore holds wherever they are moved (sceneContentHash leaves
// their transforms out). Their own indirect light comes from the VPLs at run time.
StaticGeometry rayKernelStage(const Scene& scene, const SceneBakeSettings& o, const StagePlan& plan,
                              SceneBake& result) {
  Stopwatch clock;
  const std::unique_ptr<StageProgress> stage = plan.begin(kStageRayKernel, 1);
  stage->throwIfCancelled();
  StaticGeometry statics;
  statics.scene = std::make_unique<Scene>(staticScene(scene));
  statics.geometry = std::make_unique<WorldGeometry>(flatten(*statics.scene));
  statics.kernel = makeRayKernel(*statics.geometry, o.backend);
  result.folder.manifest.measured.seconds.rayKernel = clock.lap();
  return statics;
}

nlohmann::json tileJournalKey(const Scene& scene, const SceneBakeSettings& settings, int atlasWidth,
                              int atlasHeight) {
  nlohmann::json key = bakeInputsJson(settings);
  key["bakeFormat"] = kBakeFormatVersion;
  key["tileJournalFormat"] = kTileJournalVersion;
  key["sceneHash"] = sceneHash(scene).whole;
  key["atlasWidth"] = atlasWidth;
  key["atlasHeight"] = atlasHeight;
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::absolute(scene.source, ec);
  key["scene"] = (ec ? std::filesystem::path(scene.source) : file).string();
  key["shard"] = std::to_string(settings.shard + 1) + "/" + std::to_string(settings.shards);
  return key;
}

std::vector<std::string> sceneBakeStages(const Scene& scene, const SceneBakeSettings& settings) {
  std::vector<std::string> stages = {kStageAtlas, kStageRayKernel, kStageCoverage, kStageLeakGuard,
                                     kStageIrradiance};
  if (LightmapBakeSettings{}.visibility.enabled &&
      hasBakeableVisibility(sceneAreaLights(scene), scene.lights))
    stages.push_back(kStageVisibility);
  if (settings.shards > 1 || (settings.exchange && !settings.exchange->keeper()))
    return stages;  // the merge, or the keeper, runs the rest
  stages.push_back(kStageFilters);
  if (settings.vpls > 0) stages.push_back(kStageVpls);
  stages.push_back(kStageProbes);
  return stages;
}

SceneBake bakeScene(const Scene& scene, const SceneBakeSettings& o, BakeObserver* observer) {
  const StagePlan plan(observer, sceneBakeStages(scene, o));
  const auto start = std::chrono::steady_clock::now();
  SceneBake result;
  const Atlas atlas = atlasStage(scene, o, plan, result);
  const StaticGeometry statics = rayKernelStage(scene, o, plan, result);
  const LightmapBake bake = lightmapStages(scene, statics, atlas, o, plan, result);
  if (bake.partial) {  // a shard's or a rank's tiles only: the merge or the keeper goes on
    result.partial = true;
    result.measuredPeakBytes = peakResidentBytes();
    return result;
  }
  vplStage(statics, o, plan, result);
  lightmapFolder(scene, o, atlas, bake, statics, result);
  probeStage(scene, statics, atlas, bake, o, plan, result);
  result.folder.manifest.measured.seconds.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace bounce
