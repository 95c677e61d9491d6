// Stage 1 of the scene bake (scene_bake_stages.h): the atlas, and the memory estimate it allows.
#include <stdexcept>

#include "atlas/atlas.h"
#include "pipeline/bake_memory.h"
#include "pipeline/scene_bake.h"
#include "pipeline/scene_bake_stages.h"
#include "trace/stopwatch.h"

namespace bounce {

Atlas atlasStage(const Scene& scene, const SceneBakeSettings& o, const StagePlan& plan,
                 SceneBake& result) {
  Stopwatch clock;
  const std::unique_ptr<StageProgress> stage = plan.begin(kStageAtlas, 1);
  stage->throwIfCancelled();
  AtlasSettings atlasSettings;
  atlasSettings.texelSize = o.texelSize;
  atlasSettings.texelBudget = o.texelBudget;
  atlasSettings.maxTexels = o.maxTexels;
  Atlas atlas = buildAtlas(scene, atlasSettings);
  result.notes = atlas.notes;
  if (atlas.layout.instances.empty())
    throw std::runtime_error(scene.source + " has no static surfaces to bake");
  result.folder.manifest.measured.seconds.atlas = clock.lap();
  const BakeMemoryEstimate memory =
      estimateBakeMemory(scene, atlas.layout, atlas.layout.utilisation, o);
  result.estimatedPeakBytes = memory.peak();
  if (o.maxMemory > 0.0 && memory.peak() > o.maxMemory)
    throw BakeOverMemoryBudget(
        "the bake would take about " + memory.describe() + ", over the budget of " +
        formatBytes(o.maxMemory) +
        ": coarser texels (--texel-size, --max-texels), fewer VPLs (--vpls) or fewer static "
        "triangles lower it");
  return atlas;
}

}  // namespace bounce
