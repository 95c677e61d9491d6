#include "pipeline/scene_bake.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "atlas/atlas.h"
#include "bake/light_visibility_bake.h"
#include "bake/lightmap_bake.h"
#include "bake_folder/visibility_file.h"
#include "bake_folder/vpl_file.h"
#include "pipeline/bake_memory.h"
#include "pipeline/probe_stage.h"
#include "pipeline/tile_journal.h"
#include "scene/area_lights.h"
#include "scene/world_geometry.h"
#include "trace/stopwatch.h"
#include "vpl/vpl_gather.h"
#include "vpl/vpl_generate.h"

namespace bounce {
namespace {

constexpr char kStageAtlas[] = "atlas";
constexpr char kStageRayKernel[] = "ray kernel";
constexpr char kStageVpls[] = "VPLs";

// bake.json's "vpls": what the vpls file holds (baker/vpl/vpl_generate.h, bake_folder/vpl.h).
// `area`: the static surface area the VPLs lie on, m².
BakeManifest::Vpls vplManifest(const VplSet& set, double area, const SceneBakeSettings& o) {
  BakeManifest::Vpls m;
  m.count = set.vpls.size();
  m.paths = set.paths;
  m.totalFlux = set.totalFlux();
  std::size_t last = 0;  // bounces after the deepest VPL are left out
  for (std::size_t k = 0; k < set.fluxPerBounce.size(); ++k)
    if (set.fluxPerBounce[k] != glm::dvec3(0.0)) last = k + 1;
  m.fluxPerBounce.assign(set.fluxPerBounce.begin(),
                         set.fluxPerBounce.begin() + static_cast<std::ptrdiff_t>(last));
  m.relativeError = set.relativeError;
  m.errorTarget = o.vplError;
  m.cap = o.vpls;
  m.clampDistance = vplClampDistance(area, set.vpls.size());
  return m;
}

// The bake folder's error.exr: each texel's estimated relative standard error (before
// denoising), kNoErrorEstimate where the texel has no samples of its own (uncovered padding,
// or covered with every point dropped by the leak guard and filled from its neighbours).
Image errorMap(const LightmapBake& bake) {
  Image map(bake.irradiance.width, bake.irradiance.height, glm::vec3(kNoErrorEstimate));
  for (std::size_t t = 0; t < map.pixels.size(); ++t)
    if (bake.covered[t] && !bake.invalid[t]) map.pixels[t] = glm::vec3(bake.relativeError[t]);
  return map;
}

// `layout` (instance indices into `scene`) renumbered for staticScene(scene), which keeps the
// static instances in order: the lightmap bake runs in the static scene, the folder keeps the
// file scene's numbering.
LightmapLayout staticLayout(const Scene& scene, LightmapLayout layout) {
  std::vector<uint32_t> renumbered(scene.instances.size(), 0);
  uint32_t next = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].mobility != Mobility::Dynamic) renumbered[i] = next++;
  for (InstanceLightmapUv& region : layout.instances)
    region.instance = renumbered.at(region.instance);
  return layout;
}

}  // namespace

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
  Stopwatch lap;
  const auto start = std::chrono::steady_clock::now();
  SceneBake result;

  std::unique_ptr<StageProgress> stage = plan.begin(kStageAtlas, 1);
  stage->throwIfCancelled();
  AtlasSettings atlasSettings;
  atlasSettings.texelSize = o.texelSize;
  atlasSettings.texelBudget = o.texelBudget;
  atlasSettings.maxTexels = o.maxTexels;
  const Atlas atlas = buildAtlas(scene, atlasSettings);
  result.notes = atlas.notes;
  if (atlas.layout.instances.empty())
    throw std::runtime_error(scene.source + " has no static surfaces to bake");
  const double atlasSeconds = lap.lap();
  const BakeMemoryEstimate memory =
      estimateBakeMemory(scene, atlas.layout, atlas.layout.utilisation, o);
  result.estimatedPeakBytes = memory.peak();
  if (o.maxMemory > 0.0 && memory.peak() > o.maxMemory)
    throw BakeOverMemoryBudget(
        "the bake would take about " + memory.describe() + ", over the budget of " +
        formatBytes(o.maxMemory) +
        ": coarser texels (--texel-size, --max-texels), fewer VPLs (--vpls) or fewer static "
        "triangles lower it");
  stage.reset();

  // Dynamic instances are left out of the whole bake, lightmap and VPLs alike: they have no
  // lightmap region, and where they stand at load time neither shadows nor lights the static
  // surfaces' baked light, which therefore holds wherever they are moved (sceneContentHash
  // leaves their transforms out). Their own indirect light comes from the VPLs at run time.
  stage = plan.begin(kStageRayKernel, 1);
  stage->throwIfCancelled();
  const Scene statics = staticScene(scene);
  const WorldGeometry geometry = flatten(statics);
  const auto kernel = makeRayKernel(geometry, o.backend);
  const double kernelSeconds = lap.lap();
  stage.reset();

  LightmapBakeSettings settings = defaultBakeSettings();
  settings.stages = &plan;
  // The tiles: this bake's share, those a journal or the parts already hold, where new ones go.
  LightmapTiles& tiles = settings.tiles;
  tiles.size = o.tileSize;
  tiles.shard = o.shard;
  tiles.shards = o.shards;
  tiles.exchange = o.exchange;
  const nlohmann::json key = tileJournalKey(scene, o, atlas.layout.width, atlas.layout.height);
  const auto restore = [&](TileJournal&& journal) {
    for (TileRecord& record : journal.records) tiles.restored.push_back(std::move(record));
  };
  for (const std::filesystem::path& part : o.parts) {
    TileJournal journal = readTileJournal(part);
    checkTileJournalKey(part, journal.key, key, kTileKeyNotShared);
    restore(std::move(journal));
  }
  if (!o.parts.empty()) tiles.computeMissing = false;
  std::unique_ptr<TileJournalWriter> journal;
  if (!o.journal.empty()) {
    constexpr const char* kSceneOnly[] = {"scene"};
    if (o.resume && std::filesystem::exists(o.journal)) {
      TileJournal earlier = readTileJournal(o.journal);
      checkTileJournalKey(o.journal, earlier.key, key, kSceneOnly);
      if (earlier.droppedBytes > 0)
        result.notes.push_back(o.journal.string() + ": its last " +
                               std::to_string(earlier.droppedBytes) +
                               " bytes were a tile cut short when the bake stopped: dropped");
      journal = std::make_unique<TileJournalWriter>(o.journal, earlier);
      restore(std::move(earlier));
    } else {
      journal = std::make_unique<TileJournalWriter>(o.journal, key);
    }
    tiles.finished = [&writer = *journal](const TileRecord& record) { writer.append(record); };
  }
  settings.irradiance.maxSpp = o.spp;
  settings.irradiance.targetError = o.targetError;
  settings.irradiance.maxDepth = o.maxDepth;
  settings.irradiance.seed = o.seed;
  settings.irradiance.lightChoice = o.lightChoice;
  settings.irradiance.threads = o.threads;
  settings.denoise = o.denoise;
  const LightmapBake bake =
      bakeLightmap(statics, geometry, *kernel, staticLayout(scene, atlas.layout), settings);
  lap.lap();  // the lightmap steps time themselves (bake.seconds)
  result.tiles = bake.tiles;
  result.tilesRestored = bake.tilesRestored;
  if (o.resume && bake.tilesRestored > 0)
    result.notes.push_back("resumed: " + std::to_string(bake.tilesRestored) + " of " +
                           std::to_string(bake.tilesShare) + " tiles were in " +
                           o.journal.string());
  if (bake.partial) {
    result.partial = true;
    result.measuredPeakBytes = peakResidentBytes();
    return result;
  }
  if (!bake.irradiance.allFinite())
    throw std::runtime_error("the lightmap has non-finite texels (a bug: please report)");

  VplSet vpls;
  double vplArea = 0.0;
  if (o.vpls > 0) {
    stage = plan.begin(kStageVpls, static_cast<uint64_t>(o.vpls));
    VplSettings vplSettings;
    vplSettings.maxVpls = o.vpls;
    vplSettings.relativeError = o.vplError;
    vplSettings.seed = o.seed;
    vplSettings.threads = o.threads;
    vplSettings.progress = stage.get();
    // VPL paths run in the static scene too (baker/vpl/vpl_generate.h: staticScene).
    vpls = generateVpls(statics, geometry, *kernel, vplSettings);
    vplArea = staticSurfaceArea(statics, geometry);
    stage.reset();
  }
  const double vplSeconds = lap.lap();
  ProbeStage probes =
      runProbeStage(scene, statics, geometry, *kernel, atlas.vplLitInstances, o, plan);
  lap.lap();
  // bake.json (bake_folder/bake_manifest.h): what was baked and how; run-dependent figures under
  // `measured` only.
  BakeManifest& manifest = result.folder.manifest;
  // What the map holds: every light's indirect light; direct light only of baked-only lights.
  for (const Light& light : scene.lights)
    if (light.bakeDirect) manifest.directBaked.push_back(light.name);
  for (const Material& material : scene.materials)
    if (material.bakeDirect && material.isEmissive()) manifest.directBaked.push_back(material.name);
  uint32_t fewest = 0xffffffffu, most = 0;
  for (std::size_t t = 0; t < bake.samples.size(); ++t) {
    if (!bake.covered[t] || bake.invalid[t]) continue;
    fewest = std::min(fewest, bake.samples[t]);
    most = std::max(most, bake.samples[t]);
  }
  const uint64_t valid = bake.coveredTexels - bake.invalidTexels;
  BakeManifest::Settings& s = manifest.settings;
  s.texelSize = atlas.layout.texelSize;
  s.texelBudget = o.texelSize > 0 ? 0 : o.texelBudget;
  s.maxTexels = o.maxTexels;
  s.maxSpp = o.spp;
  s.targetError = o.targetError;
  s.maxDepth = o.maxDepth;
  s.seed = o.seed;
  s.denoise = settings.denoise;
  s.lightChoice = o.lightChoice == LightChoice::ByPlace ? "place" : "power";
  s.pointsPerTexel = settings.pointsPerTexel;
  s.vpls = o.vpls;
  s.vplError = o.vplError;
  // The whole hash decides; the parts let a stale bake say what changed (bake_folder.h).
  const SceneHash hash = sceneHash(scene);
  manifest.sceneHash = hash.whole;
  for (std::size_t i = 0; i < hash.parts.size(); ++i)
    manifest.sceneParts[kScenePartNames[i]] = hash.parts[i];
  manifest.settingsHash = settingsHash(s);
  manifest.scene = std::filesystem::path(scene.source).filename().string();
  BakeManifest::Atlas& a = manifest.atlas;
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
  manifest.samples = {
      .total = bake.totalSamples,
      .perTexelMin = valid > 0 ? fewest : 0,
      .perTexelMax = most,
      .nonFinite = bake.nonFiniteSamples,
      .perTexelMean =
          valid > 0 ? static_cast<double>(bake.totalSamples) / static_cast<double>(valid) : 0.0};
  manifest.estimatedError = {
      .mean = bake.meanRelativeError, .p95 = bake.p95RelativeError, .target = o.targetError};
  manifest.leaks = {.pointsInsideGeometry = bake.pointsInside,
                    .pointsAcrossWalls = bake.pointsAcross,
                    .invalidTexelsFilled = bake.invalidTexels};
  manifest.seams = {.count = bake.seams, .relativeMismatchAfterStitching = bake.seamMismatch};
  manifest.rays = {.traced = bake.rays, .backend = kernel->name()};
  if (o.vpls > 0) manifest.vpls = vplManifest(vpls, vplArea, o);
  if (!probes.probes.grids.empty()) manifest.probes = probes.manifest;
  if (bake.visibility) {
    const VisibilityBakeReport& v = bake.visibilityReport;
    manifest.visibility = BakeManifest::Visibility{
        .lights = v.lights,
        .punctualLights = v.punctualLights,
        .slotsPerTexel = kVisibilitySlots,
        .samplesPerLight = static_cast<uint64_t>(settings.visibility.samplesPerLight),
        .texelsReached = v.texelsWithLight,
        .texelsOverSlots = v.texelsOverSlots,
        .rays = v.rays,
        .otherLightsShare = v.otherLightsShare};
  }

  result.coveredTexels = bake.coveredTexels;
  result.measuredPeakBytes = peakResidentBytes();
  BakeManifest::Measured& measured = manifest.measured;
  const double tracing = bake.seconds.leakGuard + bake.seconds.irradiance;
  measured.raysPerSecond = tracing > 0 ? static_cast<double>(bake.rays) / tracing : 0.0;
  measured.peakBytes = result.measuredPeakBytes;
  measured.estimatedPeakBytes = result.estimatedPeakBytes;
  measured.seconds = {
      .atlas = atlasSeconds,
      .rayKernel = kernelSeconds,
      .coverage = bake.seconds.coverage,
      .leakGuard = bake.seconds.leakGuard,
      .irradiance = bake.seconds.irradiance,
      .visibility = bake.seconds.visibility,
      .denoise = bake.seconds.denoise,
      .dilate = bake.seconds.dilate,
      .stitch = bake.seconds.stitch,
      .vpls = vplSeconds,
      .probes = probes.seconds,
      .total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  if (bake.visibility && bake.visibilityReport.texelsOverSlots > 0)
    result.notes.push_back(
        std::to_string(bake.visibilityReport.texelsOverSlots) + " of " +
        std::to_string(bake.visibilityReport.texelsWithLight) +
        " texels are reached by more than " + std::to_string(kVisibilitySlots) +
        " static lights: they name the " + std::to_string(kVisibilitySlots - 1) +
        " brightest and share one visible fraction among the others (" +
        std::to_string(100.0 * bake.visibilityReport.otherLightsShare).substr(0, 4) +
        "% of the unshadowed irradiance)");
  result.folder.layout = atlas.layout;
  result.folder.irradiance = bake.irradiance;
  if (o.vpls > 0) result.folder.vpls = vpls.vpls;
  result.folder.visibility = bake.visibility;
  if (!probes.probes.grids.empty()) result.folder.probes = std::move(probes.probes);
  result.notes.insert(result.notes.end(), probes.notes.begin(), probes.notes.end());
  result.folder.relativeError = errorMap(bake);
  return result;
}

}  // namespace bounce
