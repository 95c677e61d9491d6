#include "pipeline/scene_bake.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "atlas/atlas.h"
#include "bake/lightmap_bake.h"
#include "bake/visibility_file.h"
#include "bake/vpl_file.h"
#include "pipeline/bake_memory.h"
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

// bake.json's "vpls": what the vpls file holds (baker/vpl/vpl_generate.h, bake/vpl.h).
// `area`: the static surface area the VPLs lie on, m².
nlohmann::json vplManifest(const VplSet& set, double area, const SceneBakeSettings& o) {
  const auto rgb = [](glm::dvec3 v) { return nlohmann::json::array({v.r, v.g, v.b}); };
  nlohmann::json perBounce = nlohmann::json::array();
  std::size_t last = 0;  // bounces after the deepest VPL are left out
  for (std::size_t k = 0; k < set.fluxPerBounce.size(); ++k)
    if (set.fluxPerBounce[k] != glm::dvec3(0.0)) last = k + 1;
  for (std::size_t k = 0; k < last; ++k) perBounce.push_back(rgb(set.fluxPerBounce[k]));
  return {{"file", kVplFileName},
          {"count", set.vpls.size()},
          {"paths", set.paths},
          {"unit", "W"},
          {"holds",
           "indirect light only: one VPL per diffuse hit of a light path from the first bounce "
           "on; flux already multiplied by the albedo of its surface; it adds "
           "Phi/pi cos(theta_vpl) cos(theta_x) / d^2 rho_x/pi (docs/vpl.md)"},
          {"totalFlux", rgb(set.totalFlux())},
          {"fluxPerBounce", perBounce},
          {"relativeError", set.relativeError},
          {"errorTarget", o.vplError},
          {"cap", o.vpls},
          {"clampDistance", vplClampDistance(area, set.vpls.size())}};
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

// FNV-1a (64 bit) of the settings that change the lightmap, hex.
std::string settingsHash(const nlohmann::json& settings) {
  uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : settings.dump()) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
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

SceneBakeSettings::SceneBakeSettings() {
  const LightmapBakeSettings defaults = defaultBakeSettings();
  maxTexels = kDefaultMaxTexels;
  spp = defaults.irradiance.maxSpp;
  targetError = defaults.irradiance.targetError;
  maxDepth = defaults.irradiance.maxDepth;
  denoise = defaults.denoise;
  vpls = VplSettings{}.maxVpls;
  vplError = VplSettings{}.relativeError;
}

std::vector<std::string> sceneBakeStages(const Scene& scene, const SceneBakeSettings& settings) {
  std::vector<std::string> stages = {kStageAtlas, kStageRayKernel, kStageCoverage, kStageLeakGuard,
                                     kStageIrradiance};
  if (LightmapBakeSettings{}.visibility.enabled && sceneAreaLights(scene).staticCount() > 0)
    stages.push_back(kStageVisibility);
  stages.push_back(kStageFilters);
  if (settings.vpls > 0) stages.push_back(kStageVpls);
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
  settings.irradiance.maxSpp = o.spp;
  settings.irradiance.targetError = o.targetError;
  settings.irradiance.maxDepth = o.maxDepth;
  settings.irradiance.seed = o.seed;
  settings.irradiance.threads = o.threads;
  settings.denoise = o.denoise;
  const LightmapBake bake =
      bakeLightmap(statics, geometry, *kernel, staticLayout(scene, atlas.layout), settings);
  lap.lap();  // the lightmap steps time themselves (bake.seconds)
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
  // What the map holds: every light's indirect light; direct light only of baked-only lights.
  nlohmann::json bakedDirect = nlohmann::json::array();
  for (const Light& light : scene.lights)
    if (light.bakeDirect) bakedDirect.push_back(light.name);
  for (const Material& material : scene.materials)
    if (material.bakeDirect && material.isEmissive()) bakedDirect.push_back(material.name);
  uint32_t fewest = 0xffffffffu, most = 0;
  for (std::size_t t = 0; t < bake.samples.size(); ++t) {
    if (!bake.covered[t] || bake.invalid[t]) continue;
    fewest = std::min(fewest, bake.samples[t]);
    most = std::max(most, bake.samples[t]);
  }
  const uint64_t valid = bake.coveredTexels - bake.invalidTexels;
  const nlohmann::json settingsJson = {{"texelSize", atlas.layout.texelSize},
                                       {"texelBudget", o.texelSize > 0 ? 0 : o.texelBudget},
                                       {"maxTexels", o.maxTexels},
                                       {"maxSpp", o.spp},
                                       {"targetError", o.targetError},
                                       {"maxDepth", o.maxDepth},
                                       {"seed", o.seed},
                                       {"denoise", settings.denoise},
                                       {"pointsPerTexel", settings.pointsPerTexel},
                                       {"vpls", o.vpls},
                                       {"vplError", o.vplError}};
  const double totalSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The whole hash decides; the parts let a stale bake say what changed (bake_folder.h).
  const SceneHash hash = sceneHash(scene);
  nlohmann::json sceneParts = nlohmann::json::object();
  for (std::size_t i = 0; i < hash.parts.size(); ++i)
    sceneParts[kScenePartNames[i]] = hash.parts[i];
  nlohmann::json manifest = {
      {"formatVersion", kBakeFormatVersion},
      {"sceneHash", hash.whole},
      {"sceneParts", sceneParts},
      {"settingsHash", settingsHash(settingsJson)},
      {"scene", std::filesystem::path(scene.source).filename().string()},
      {"settings", settingsJson},
      {"lightmap",
       {{"quantity", "irradiance"},
        {"unit", "W/m^2"},
        {"holds",
         "indirect light (two or more reflections counted at the viewer, i.e. light that "
         "reflected at least once before reaching the texel) of every light and emitter, plus "
         "the direct light of the baked-only lights listed in directBaked"},
        {"indirect", "all"},
        {"directBaked", bakedDirect}}},
      {"atlas",
       {{"width", atlas.layout.width},
        {"height", atlas.layout.height},
        {"texelSize", atlas.layout.texelSize},
        {"texelRule", atlas.texelRule},
        {"staticArea", atlas.staticArea},
        {"weightedArea", atlas.weightedArea},
        {"padding", atlas.layout.padding},
        {"charts", atlas.layout.chartCount},
        {"vplLitInstances", atlas.vplLitInstances.size()},
        {"utilisation", atlas.layout.utilisation},
        {"coveredTexels", bake.coveredTexels},
        {"invalidTexels", bake.invalidTexels},
        {"notes", atlas.notes}}},
      {"samples",
       {{"total", bake.totalSamples},
        {"perTexelMean",
         valid > 0 ? static_cast<double>(bake.totalSamples) / static_cast<double>(valid) : 0.0},
        {"perTexelMin", valid > 0 ? fewest : 0},
        {"perTexelMax", most},
        {"nonFinite", bake.nonFiniteSamples}}},
      {"estimatedError",
       {{"what",
         "relative standard error of each texel's irradiance (luminance), from its "
         "sample variance; before denoising"},
        {"file", "error.exr"},
        {"mean", bake.meanRelativeError},
        {"p95", bake.p95RelativeError},
        {"target", o.targetError}}},
      {"leaks",
       {{"pointsInsideGeometry", bake.pointsInside},
        {"pointsAcrossWalls", bake.pointsAcross},
        {"invalidTexelsFilled", bake.invalidTexels}}},
      {"seams", {{"count", bake.seams}, {"relativeMismatchAfterStitching", bake.seamMismatch}}},
      {"rays",
       {{"traced", bake.rays},
        {"perSecond",
         bake.seconds.leakGuard + bake.seconds.irradiance > 0
             ? static_cast<double>(bake.rays) / (bake.seconds.leakGuard + bake.seconds.irradiance)
             : 0.0},
        {"backend", kernel->name()}}},
      {"seconds",
       {{"atlas", atlasSeconds},
        {"rayKernel", kernelSeconds},
        {"coverage", bake.seconds.coverage},
        {"leakGuard", bake.seconds.leakGuard},
        {"irradiance", bake.seconds.irradiance},
        {"visibility", bake.seconds.visibility},
        {"denoise", bake.seconds.denoise},
        {"dilate", bake.seconds.dilate},
        {"stitch", bake.seconds.stitch},
        {"vpls", vplSeconds},
        {"total", totalSeconds}}}};
  if (o.vpls > 0) manifest["vpls"] = vplManifest(vpls, vplArea, o);
  if (bake.visibility) {
    const VisibilityBakeReport& v = bake.visibilityReport;
    manifest["visibility"] = {
        {"file", kVisibilityFileName},
        {"what",
         "per texel, the visible fraction V of each static area light's unshadowed irradiance "
         "(bake/light_visibility.h); the renderer multiplies its exact polygon irradiance by it"},
        {"lights", v.lights},
        {"slotsPerTexel", kVisibilitySlots},
        {"samplesPerLight", settings.visibility.samplesPerLight},
        {"texelsReached", v.texelsWithLight},
        {"texelsOverSlots", v.texelsOverSlots},
        {"otherLightsShare", v.otherLightsShare},
        {"rays", v.rays},
        {"seconds", bake.seconds.visibility}};
  }

  result.coveredTexels = bake.coveredTexels;
  result.measuredPeakBytes = peakResidentBytes();
  manifest["memory"] = {{"estimatedPeak", result.estimatedPeakBytes},
                        {"measuredPeak", result.measuredPeakBytes},
                        {"unit", "bytes"},
                        {"what",
                         "resident set: estimated after the atlas (bake_memory.h), "
                         "measured at the end (the process's peak)"}};
  if (bake.visibility && bake.visibilityReport.texelsOverSlots > 0)
    result.notes.push_back(
        std::to_string(bake.visibilityReport.texelsOverSlots) + " of " +
        std::to_string(bake.visibilityReport.texelsWithLight) +
        " texels are reached by more than " + std::to_string(kVisibilitySlots) +
        " static area lights: they name the " + std::to_string(kVisibilitySlots - 1) +
        " brightest and share one visible fraction among the others (" +
        std::to_string(100.0 * bake.visibilityReport.otherLightsShare).substr(0, 4) +
        "% of the unshadowed irradiance)");
  result.folder.layout = atlas.layout;
  result.folder.irradiance = bake.irradiance;
  if (o.vpls > 0) result.folder.vpls = vpls.vpls;
  result.folder.visibility = bake.visibility;
  result.folder.relativeError = errorMap(bake);
  result.folder.manifestJson = manifest.dump(1) + "\n";
  result.manifest = std::move(manifest);
  return result;
}

}  // namespace bounce
