#include "pipeline/probe_stage.h"

#include <algorithm>
#include <cstdio>

#include "atlas/atlas.h"
#include "bake/corner_visibility_bake.h"
#include "bake/irradiance_cache.h"
#include "bake/irradiance_probes.h"
#include "bake/light_visibility_bake.h"
#include "bake/lightmap_bake.h"
#include "bake_folder/gather.h"
#include "pipeline/scene_bake.h"
#include "pipeline/scene_bake_stages.h"
#include "scene/static_scene.h"

namespace bounce {

ProbeStage runProbeStage(const Scene& scene, const Scene& statics, const WorldGeometry& geometry,
                         const RayKernel& kernel, std::span<const uint32_t> withoutRegion,
                         const IndirectCache* lightmap, double errorFloor,
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
  settings.cache = lightmap;
  settings.errorFloor = errorFloor;
  ProbeBake bake = bakeIrradianceProbes(statics, geometry, kernel, instances, settings);
  out.probes = std::move(bake.probes);
  // Their direct light is drawn live: the static lights' visibility per triangle corner, as the
  // texels have it per texel (corner_visibility_bake.h).
  const AreaLightSet lights = sceneAreaLights(statics);
  if (LightmapBakeSettings{}.visibility.enabled && hasBakeableVisibility(lights, statics.lights)) {
    std::vector<uint32_t> tracedInstances;
    std::vector<uint8_t> mirrored;
    for (const ProbedInstance& p : instances) {
      tracedInstances.push_back(p.tracedIndex);
      mirrored.push_back(
          glm::determinant(glm::mat3(scene.instances[p.fileIndex].transform)) < 0.0f ? 1 : 0);
    }
    CornerVisibilitySettings corner;  // kCornerSamplesPerLight samples a light
    corner.seed = o.seed;
    corner.threads = o.threads;
    CornerVisibilityBake v = bakeCornerVisibility(lights, statics.lights, geometry, kernel,
                                                  tracedInstances, mirrored, corner);
    // Each grid's corners in the grids' order (probe_file.h: consecutive, none unused).
    ProbeVisibility& visibility = out.probes.visibility;
    visibility.lightCount = v.visibility.lightCount;
    visibility.punctualCount = v.visibility.punctualCount;
    for (ProbeGrid& g : out.probes.grids)
      for (std::size_t i = 0; i < instances.size(); ++i)
        if (instances[i].fileIndex == g.instance) {
          g.firstCorner = static_cast<uint32_t>(visibility.corners.size());
          g.cornerCount = v.cornerCount[i];
          const auto from = v.visibility.corners.begin() + v.firstCorner[i];
          visibility.corners.insert(visibility.corners.end(), from, from + v.cornerCount[i]);
        }
    out.visibilityRays = v.rays;
    out.visibilityVertices = v.vertices;
    out.visibilitySeconds = v.seconds;
  }
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

namespace {

// The probes' error floor (W/m²): --error-floor times the delivered map's mean luminance over the
// texels the leak guard kept, the light the probes themselves gather (indirect). From the map,
// so a merge and a single process agree (the cache pass's mean exists only where tiles ran).
double probeErrorFloor(const LightmapBake& bake, const SceneBakeSettings& settings) {
  if (!(settings.errorFloor > 0.0f)) return 0.0;
  return static_cast<double>(settings.errorFloor) *
         meanLuminance(bake.irradiance, keptTexels(bake));
}

}  // namespace

void probeStage(const Scene& scene, const StaticGeometry& statics, const Atlas& atlas,
                const LightmapBake& bake, const SceneBakeSettings& settings, const StagePlan& plan,
                SceneBake& result) {
  // With the cache gather the probes' paths end at the delivered map after one reflection.
  const std::unique_ptr<IrradianceCache> lightmap =
      settings.gather == Gather::Cache ? deliveredMapCache(*statics.scene, *statics.geometry,
                                                           staticLayout(scene, atlas.layout), bake)
                                       : nullptr;
  ProbeStage probes = runProbeStage(scene, *statics.scene, *statics.geometry, *statics.kernel,
                                    atlas.vplLitInstances, lightmap ? &lightmap->half(0) : nullptr,
                                    probeErrorFloor(bake, settings), settings, plan);
  // The stage's seconds: the probes' and their instances' baked visibility.
  result.folder.manifest.measured.seconds.probes = probes.seconds + probes.visibilitySeconds;
  if (!probes.probes.visibility.corners.empty()) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f", probes.visibilitySeconds);
    result.notes.push_back("the static lights' visibility on the probe-lit instances: " +
                           std::to_string(probes.probes.visibility.corners.size()) +
                           " triangle corners at " + std::to_string(probes.visibilityVertices) +
                           " vertices, " + std::to_string(probes.visibilityRays) +
                           " occlusion rays, " + seconds + " s");
  }
  if (!probes.probes.grids.empty()) {
    result.folder.manifest.probes = probes.manifest;
    result.folder.probes = std::move(probes.probes);
  }
  result.notes.insert(result.notes.end(), probes.notes.begin(), probes.notes.end());
}

}  // namespace bounce
