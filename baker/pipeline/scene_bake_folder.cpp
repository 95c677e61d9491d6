// The scene bake's folder (scene_bake_stages.h): the lightmap's files and bake.json
// (bake_folder/bake_manifest.h): what was baked and how; run-dependent figures under `measured`
// only.
#include <algorithm>
#include <filesystem>
#include <string>

#include "atlas/atlas.h"
#include "bake/lightmap_bake.h"
#include "bake_folder/visibility_file.h"
#include "pipeline/bake_memory.h"
#include "pipeline/scene_bake.h"
#include "pipeline/scene_bake_stages.h"
#include "ray/ray_kernel.h"

namespace bounce {
namespace {

// The bake folder's error.exr: each texel's estimated relative error of the delivered map
// (delivered_error.h; 0 where the delivered E is 0), kNoErrorEstimate where the texel has no
// samples of its own (uncovered padding, or covered with every point dropped by the leak guard
// and filled from its neighbours).
Image errorMap(const LightmapBake& bake) {
  Image map(bake.irradiance.width, bake.irradiance.height, glm::vec3(kNoErrorEstimate));
  for (std::size_t t = 0; t < map.pixels.size(); ++t)
    if (bake.covered[t] && !bake.invalid[t])
      map.pixels[t] = glm::vec3(std::max(bake.delivered.perTexel[t], 0.0f));
  return map;
}

// What the map holds: every light's indirect light; direct light only of baked-only lights.
std::vector<std::string> directBaked(const Scene& scene) {
  std::vector<std::string> names;
  for (const Light& light : scene.lights)
    if (light.bakeDirect) names.push_back(light.name);
  for (const Material& material : scene.materials)
    if (material.bakeDirect && material.isEmissive()) names.push_back(material.name);
  return names;
}

BakeManifest::Atlas atlasManifest(const Atlas& atlas, const LightmapBake& bake) {
  BakeManifest::Atlas a;
  a.width = atlas.layout.width;
  a.height = atlas.layout.height;
  a.texelSize = atlas.layout.texelSize;
  a.texelRule = atlas.texelRule;
  a.staticArea = atlas.staticArea;
  a.weightedArea = atlas.weightedArea;
  a.padding = atlas.layout.padding;
  a.charts = atlas.layout.chartCount;
  a.regions = atlas.layout.instances.size();
  a.vplLitInstances = atlas.vplLitInstances.size();
  a.utilisation = atlas.layout.utilisation;
  a.coveredTexels = bake.coveredTexels;
  a.invalidTexels = bake.invalidTexels;
  a.notes = atlas.notes;
  return a;
}

// Samples per valid covered texel: the fewest, the most and the mean.
BakeManifest::Samples samplesManifest(const LightmapBake& bake) {
  uint32_t fewest = 0xffffffffu, most = 0;
  for (std::size_t t = 0; t < bake.samples.size(); ++t) {
    if (!bake.covered[t] || bake.invalid[t]) continue;
    fewest = std::min(fewest, bake.samples[t]);
    most = std::max(most, bake.samples[t]);
  }
  const uint64_t valid = bake.coveredTexels - bake.invalidTexels;
  return {.total = bake.totalSamples,
          .perTexelMin = valid > 0 ? fewest : 0,
          .perTexelMax = most,
          .nonFinite = bake.nonFiniteSamples,
          .perTexelMean = valid > 0
                              ? static_cast<double>(bake.totalSamples) / static_cast<double>(valid)
                              : 0.0};
}

BakeManifest::Visibility visibilityManifest(const VisibilityBakeReport& v) {
  return {
      .lights = v.lights,
      .punctualLights = v.punctualLights,
      .slotsPerTexel = kVisibilitySlots,
      .samplesPerLight = static_cast<uint64_t>(defaultBakeSettings().visibility.samplesPerLight),
      .texelsReached = v.texelsWithLight,
      .texelsOverSlots = v.texelsOverSlots,
      .rays = v.rays,
      .otherLightsShare = v.otherLightsShare};
}

// The run's figures: rays per second, memory, each lightmap step's seconds.
void measure(const LightmapBake& bake, SceneBake& result) {
  BakeManifest::Measured& measured = result.folder.manifest.measured;
  const double tracing = bake.seconds.leakGuard + bake.seconds.irradiance;
  measured.raysPerSecond = tracing > 0 ? static_cast<double>(bake.rays) / tracing : 0.0;
  result.measuredPeakBytes = peakResidentBytes();
  measured.peakBytes = result.measuredPeakBytes;
  measured.estimatedPeakBytes = result.estimatedPeakBytes;
  BakeManifest::Measured::Seconds& t = measured.seconds;
  t.coverage = bake.seconds.coverage;
  t.leakGuard = bake.seconds.leakGuard;
  t.irradiance = bake.seconds.irradiance;
  t.visibility = bake.seconds.visibility;
  t.denoise = bake.seconds.denoise;
  t.dilate = bake.seconds.dilate;
  t.stitch = bake.seconds.stitch;
}

std::string visibilityNote(const VisibilityBakeReport& v) {
  return std::to_string(v.texelsOverSlots) + " of " + std::to_string(v.texelsWithLight) +
         " texels are reached by more than " + std::to_string(kVisibilitySlots) +
         " static lights: they name the " + std::to_string(kVisibilitySlots - 1) +
         " brightest and share one visible fraction among the others (" +
         std::to_string(100.0 * v.otherLightsShare).substr(0, 4) +
         "% of the unshadowed irradiance)";
}

}  // namespace

void lightmapFolder(const Scene& scene, const SceneBakeSettings& o, const Atlas& atlas,
                    const LightmapBake& bake, const StaticGeometry& statics, SceneBake& result) {
  BakeManifest& manifest = result.folder.manifest;
  manifest.directBaked = directBaked(scene);
  // The settings as resolved: the texel size the atlas chose, a budget only where none was given.
  manifest.settings = o;
  manifest.settings.texelSize = atlas.layout.texelSize;
  manifest.settings.texelBudget = o.texelSize > 0 ? 0 : o.texelBudget;
  manifest.settingsHash = settingsHash(manifest.settings);
  // The whole hash decides; the parts let a stale bake say what changed (bake_folder.h).
  const SceneHash hash = sceneHash(scene);
  manifest.sceneHash = hash.whole;
  for (std::size_t i = 0; i < hash.parts.size(); ++i)
    manifest.sceneParts[kScenePartNames[i]] = hash.parts[i];
  manifest.scene = std::filesystem::path(scene.source).filename().string();
  manifest.atlas = atlasManifest(atlas, bake);
  manifest.samples = samplesManifest(bake);
  manifest.estimatedError = {.mean = bake.delivered.mean,
                             .p95 = bake.delivered.p95,
                             .luminanceWeighted = bake.delivered.luminanceWeighted,
                             .target = o.targetError,
                             .beforeFiltersMean = bake.meanRelativeError,
                             .beforeFiltersP95 = bake.p95RelativeError,
                             .unknownTexels = bake.delivered.unknownTexels};
  manifest.leaks = {.pointsInsideGeometry = bake.pointsInside,
                    .pointsAcrossWalls = bake.pointsAcross,
                    .invalidTexelsFilled = bake.invalidTexels};
  manifest.seams = {.count = bake.seams, .relativeMismatchAfterStitching = bake.seamMismatch};
  manifest.rays = {.traced = bake.rays, .backend = statics.kernel->name()};
  if (bake.visibility) manifest.visibility = visibilityManifest(bake.visibilityReport);
  result.coveredTexels = bake.coveredTexels;
  measure(bake, result);
  if (bake.visibility && bake.visibilityReport.texelsOverSlots > 0)
    result.notes.push_back(visibilityNote(bake.visibilityReport));
  result.folder.layout = atlas.layout;
  result.folder.irradiance = bake.irradiance;
  result.folder.visibility = bake.visibility;
  result.folder.relativeError = errorMap(bake);
}

}  // namespace bounce
