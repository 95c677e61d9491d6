#include "pipeline/probe_stage.h"

#include <algorithm>

#include "atlas/atlas.h"
#include "bake/irradiance_probes.h"
#include "pipeline/scene_bake.h"
#include "pipeline/scene_bake_stages.h"
#include "scene/static_scene.h"

namespace bounce {

ProbeStage runProbeStage(const Scene& scene, const Scene& statics, const WorldGeometry& geometry,
                         const RayKernel& kernel, std::span<const uint32_t> withoutRegion,
                         const SceneBakeSettings& o, const StagePlan& plan) {
  // Instance i of the file is traced as its number in staticScene (scene/static_scene.h).
  const std::vector<uint32_t> traced = staticInstanceNumbers(scene);
  std::vector<ProbedInstance> instances;
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (traced[i] != kNotStatic &&
        std::binary_search(withoutRegion.begin(), withoutRegion.end(), i))
      instances.push_back({.fileIndex = i, .tracedIndex = traced[i]});
  const std::vector<ProbeGrid> grids = placeProbeGrids(geometry, instances);
  uint64_t count = 0;
  for (const ProbeGrid& g : grids) count += g.probeCount();  // the stage's work items
  std::unique_ptr<StageProgress> stage = plan.begin(kStageProbes, count);
  stage->throwIfCancelled();
  ProbeStage out;
  if (instances.empty()) return out;
  ProbeSettings settings;
  settings.maxSpp = o.maxSpp;
  settings.targetError = o.targetError;
  settings.maxDepth = o.maxDepth;
  settings.seed = o.seed;
  settings.lightChoice = o.lightChoice;
  settings.threads = o.threads;
  settings.progress = stage.get();
  ProbeBake bake = bakeIrradianceProbes(statics, geometry, kernel, instances, settings);
  out.probes = std::move(bake.probes);
  BakeManifest::Probes& m = out.manifest;
  m.count = out.probes.probes.size();
  m.grids = out.probes.grids.size();
  m.targetError = o.targetError;
  m.leakTestRays = bake.rays;
  m.samplesTotal = bake.totalSamples;
  double errorSum = 0.0;
  uint64_t valid = 0;
  uint32_t fewest = 0xffffffffu, most = 0;
  for (std::size_t i = 0; i < bake.samples.size(); ++i) {
    if (!bake.needed[i]) {
      ++m.unread;
      continue;
    }
    if (bake.invalid[i]) {
      ++m.invalidFilled;
      continue;
    }
    ++valid;
    errorSum += bake.relativeError[i];
    fewest = std::min(fewest, bake.samples[i]);
    most = std::max(most, bake.samples[i]);
  }
  m.samplesPerProbeMin = valid > 0 ? fewest : 0;
  m.samplesPerProbeMax = most;
  m.meanRelativeError = valid > 0 ? errorSum / static_cast<double>(valid) : 0.0;
  m.invalidFilled -= bake.unfilled;
  if (bake.unfilled > 0)
    out.notes.push_back(std::to_string(bake.unfilled) +
                        " irradiance probes lie inside geometry or behind a wall with no valid "
                        "probe of their grid beside them: left dark");
  out.seconds = bake.seconds;
  return out;
}

void probeStage(const Scene& scene, const StaticGeometry& statics, const Atlas& atlas,
                const SceneBakeSettings& settings, const StagePlan& plan, SceneBake& result) {
  ProbeStage probes = runProbeStage(scene, *statics.scene, *statics.geometry, *statics.kernel,
                                    atlas.vplLitInstances, settings, plan);
  result.folder.manifest.measured.seconds.probes = probes.seconds;
  if (!probes.probes.grids.empty()) {
    result.folder.manifest.probes = probes.manifest;
    result.folder.probes = std::move(probes.probes);
  }
  result.notes.insert(result.notes.end(), probes.notes.begin(), probes.notes.end());
}

}  // namespace bounce
