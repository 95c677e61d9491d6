// bounce-bake: bakes a scene's lightmap (irradiance E in W/m² per texel of the atlas) and writes
// the bake folder (engine/bake/bake_folder.h): lightmap.exr, layout.bin, bake.json, and the
// virtual point lights (vpls, baker/vpl) unless --vpls 0.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "atlas/atlas.h"
#include "bake/bake_folder.h"
#include "bake/lightmap_bake.h"
#include "bake/visibility_file.h"
#include "bake/vpl_file.h"
#include "image/image_io.h"
#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "scene/world_geometry.h"
#include "trace/progress_line.h"
#include "trace/sampling.h"
#include "vpl/vpl_gather.h"
#include "vpl/vpl_generate.h"

namespace {

const bounce::LightmapBakeSettings kDefaults = bounce::defaultBakeSettings();

struct Options {
  std::filesystem::path scene;
  std::filesystem::path out;
  float texelSize = 0.0f;
  int texelBudget = 0;  // 0: the density rule (atlas/texel_density.h)
  int64_t maxTexels = bounce::kDefaultMaxTexels;
  int spp = kDefaults.irradiance.maxSpp;
  float targetError = kDefaults.irradiance.targetError;
  int maxDepth = kDefaults.irradiance.maxDepth;
  uint32_t seed = 0;
  int threads = 0;
  std::string backend = "embree";
  std::string denoise = kDefaults.denoise ? "on" : "off";
  std::filesystem::path png;
  float exposure = 0.0f;
  bool progress = false;
  bool quiet = false;
  int vpls = bounce::VplSettings{}.maxVpls;
  float vplError = bounce::VplSettings{}.relativeError;
};

// bake.json's "vpls": what the vpls file holds (baker/vpl/vpl_generate.h, bake/vpl.h).
// `area`: the static surface area the VPLs lie on, m².
nlohmann::json vplManifest(const bounce::VplSet& set, double area, const Options& o) {
  const auto rgb = [](glm::dvec3 v) { return nlohmann::json::array({v.r, v.g, v.b}); };
  nlohmann::json perBounce = nlohmann::json::array();
  std::size_t last = 0;  // bounces after the deepest VPL are left out
  for (std::size_t k = 0; k < set.fluxPerBounce.size(); ++k)
    if (set.fluxPerBounce[k] != glm::dvec3(0.0)) last = k + 1;
  for (std::size_t k = 0; k < last; ++k) perBounce.push_back(rgb(set.fluxPerBounce[k]));
  return {{"file", bounce::kVplFileName},
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
          {"clampDistance", bounce::vplClampDistance(area, set.vpls.size())}};
}

// The bake folder's error.exr: each texel's estimated relative standard error (before
// denoising), kNoErrorEstimate where the texel has no samples of its own (uncovered padding,
// or covered with every point dropped by the leak guard and filled from its neighbours).
bounce::Image errorMap(const bounce::LightmapBake& bake) {
  bounce::Image map(bake.irradiance.width, bake.irradiance.height,
                    glm::vec3(bounce::kNoErrorEstimate));
  for (std::size_t t = 0; t < map.pixels.size(); ++t)
    if (bake.covered[t] && !bake.invalid[t]) map.pixels[t] = glm::vec3(bake.relativeError[t]);
  return map;
}

double since(std::chrono::steady_clock::time_point& last) {
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - last).count();
  last = now;
  return s;
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
bounce::LightmapLayout staticLayout(const bounce::Scene& scene, bounce::LightmapLayout layout) {
  std::vector<uint32_t> renumbered(scene.instances.size(), 0);
  uint32_t next = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].mobility != bounce::Mobility::Dynamic) renumbered[i] = next++;
  for (bounce::InstanceLightmapUv& region : layout.instances)
    region.instance = renumbered.at(region.instance);
  return layout;
}

int run(const Options& o) {
  auto clock = std::chrono::steady_clock::now();
  const auto start = clock;
  const bounce::Scene scene = bounce::loadScene(o.scene);
  for (const std::string& warning : scene.warnings)
    std::fprintf(stderr, "bounce-bake: warning: %s\n", warning.c_str());
  const double loadSeconds = since(clock);

  bounce::AtlasSettings atlasSettings;
  atlasSettings.texelSize = o.texelSize;
  atlasSettings.texelBudget = o.texelBudget;
  atlasSettings.maxTexels = o.maxTexels;
  const bounce::Atlas atlas = bounce::buildAtlas(scene, atlasSettings);
  for (const std::string& note : atlas.notes)
    std::fprintf(stderr, "bounce-bake: note: %s\n", note.c_str());
  if (atlas.layout.instances.empty())
    throw std::runtime_error(o.scene.string() + " has no static surfaces to bake");
  const double atlasSeconds = since(clock);

  // Dynamic instances are left out of the whole bake, lightmap and VPLs alike: they have no
  // lightmap region, and where they stand at load time neither shadows nor lights the static
  // surfaces' baked light, which therefore holds wherever they are moved (sceneContentHash
  // leaves their transforms out). Their own indirect light comes from the VPLs at run time.
  const bounce::Scene statics = bounce::staticScene(scene);
  const bounce::RayBackend backend = bounce::parseRayBackend(o.backend);
  const bounce::WorldGeometry geometry = bounce::flatten(statics);
  const auto kernel = bounce::makeRayKernel(geometry, backend);
  const double kernelSeconds = since(clock);

  bounce::LightmapBakeSettings settings = kDefaults;
  settings.irradiance.maxSpp = o.spp;
  settings.irradiance.targetError = o.targetError;
  settings.irradiance.maxDepth = o.maxDepth;
  settings.irradiance.seed = o.seed;
  settings.irradiance.threads = o.threads;
  settings.irradiance.progress = !o.quiet && (o.progress || bounce::stderrIsTerminal());
  settings.denoise = o.denoise == "on";
  const bounce::LightmapBake bake =
      bounce::bakeLightmap(statics, geometry, *kernel, staticLayout(scene, atlas.layout), settings);
  const double bakeSeconds = since(clock);
  if (!bake.irradiance.allFinite())
    throw std::runtime_error("the lightmap has non-finite texels (a bug: please report)");

  bounce::VplSet vpls;
  double vplArea = 0.0;
  if (o.vpls > 0) {
    bounce::VplSettings vplSettings;
    vplSettings.maxVpls = o.vpls;
    vplSettings.relativeError = o.vplError;
    vplSettings.seed = o.seed;
    vplSettings.threads = o.threads;
    // VPL paths run in the static scene too (baker/vpl/vpl_generate.h: staticScene).
    vpls = bounce::generateVpls(statics, geometry, *kernel, vplSettings);
    vplArea = bounce::surfaceArea(geometry);
  }
  const double vplSeconds = since(clock);

  // What the map holds: every light's indirect light; direct light only of baked-only lights.
  nlohmann::json bakedDirect = nlohmann::json::array();
  for (const bounce::Light& light : scene.lights)
    if (light.bakeDirect) bakedDirect.push_back(light.name);
  for (const bounce::Material& material : scene.materials)
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
  const bounce::SceneHash hash = bounce::sceneHash(scene);
  nlohmann::json sceneParts = nlohmann::json::object();
  for (std::size_t i = 0; i < hash.parts.size(); ++i)
    sceneParts[bounce::kScenePartNames[i]] = hash.parts[i];
  nlohmann::json manifest = {
      {"formatVersion", bounce::kBakeFormatVersion},
      {"sceneHash", hash.whole},
      {"sceneParts", sceneParts},
      {"settingsHash", settingsHash(settingsJson)},
      {"scene", o.scene.filename().string()},
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
       {{"load", loadSeconds},
        {"atlas", atlasSeconds},
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
    const bounce::VisibilityBakeReport& v = bake.visibilityReport;
    manifest["visibility"] = {
        {"file", bounce::kVisibilityFileName},
        {"what",
         "per texel, the visible fraction V of each static area light's unshadowed irradiance "
         "(bake/light_visibility.h); the renderer multiplies its exact polygon irradiance by it"},
        {"lights", v.lights},
        {"slotsPerTexel", bounce::kVisibilitySlots},
        {"samplesPerLight", settings.visibility.samplesPerLight},
        {"texelsReached", v.texelsWithLight},
        {"texelsOverSlots", v.texelsOverSlots},
        {"otherLightsShare", v.otherLightsShare},
        {"rays", v.rays},
        {"seconds", bake.seconds.visibility}};
  }

  const std::filesystem::path out =
      o.out.empty() ? std::filesystem::path(o.scene).replace_extension(".bake") : o.out;
  bounce::Bake folder;
  folder.layout = atlas.layout;
  folder.irradiance = bake.irradiance;
  folder.manifestJson = manifest.dump(1) + "\n";
  if (o.vpls > 0) folder.vpls = vpls.vpls;
  folder.visibility = bake.visibility;
  folder.relativeError = errorMap(bake);
  bounce::writeBake(out, folder);
  if (!o.png.empty()) {
    // A white Lambertian surface's radiance E/π, tone-mapped: what the map looks like.
    bounce::Image radiance = bake.irradiance;
    for (glm::vec3& p : radiance.pixels) p *= bounce::kInvPi;
    bounce::writePng(o.png, radiance, o.exposure);
  }
  std::fprintf(
      stderr,
      "bounce-bake: %s: atlas %dx%d (%d charts, %.0f%% used, texel %.4g m), %llu "
      "texels, %.0f spp mean, estimated error mean %.2f%% p95 %.2f%%, %.2f Mrays/s, "
      "%.2f s (irradiance %.2f s) -> %s\n",
      o.scene.filename().string().c_str(), atlas.layout.width, atlas.layout.height,
      atlas.layout.chartCount, 100.0 * atlas.layout.utilisation,
      static_cast<double>(atlas.layout.texelSize),
      static_cast<unsigned long long>(bake.coveredTexels),
      valid > 0 ? static_cast<double>(bake.totalSamples) / static_cast<double>(valid) : 0.0,
      100.0 * bake.meanRelativeError, 100.0 * bake.p95RelativeError,
      manifest["rays"]["perSecond"].get<double>() * 1e-6, bakeSeconds + since(clock),
      bake.seconds.irradiance, out.string().c_str());
  if (bake.visibility && bake.visibilityReport.texelsOverSlots > 0)
    std::fprintf(stderr,
                 "bounce-bake: note: %llu of %llu texels are reached by more than %d static area "
                 "lights: they name the %d brightest and share one visible fraction among the "
                 "others (%.1f%% of the unshadowed irradiance)\n",
                 static_cast<unsigned long long>(bake.visibilityReport.texelsOverSlots),
                 static_cast<unsigned long long>(bake.visibilityReport.texelsWithLight),
                 bounce::kVisibilitySlots, bounce::kVisibilitySlots - 1,
                 100.0 * bake.visibilityReport.otherLightsShare);
  if (bake.nonFiniteSamples > 0)
    std::fprintf(stderr,
                 "bounce-bake: warning: %llu samples were non-finite (NaN or infinite scene data "
                 "in %s?) and counted as black: the affected texels are biased low\n",
                 static_cast<unsigned long long>(bake.nonFiniteSamples), o.scene.string().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "bounce-bake: bakes a scene's lightmap, irradiance E in W/m² per texel (by default the "
      "indirect light; lights marked extras.bounce.bake = \"all\" also their direct light), "
      "into a bake folder (lightmap.exr, layout.bin, bake.json)."};
  Options o;
  app.option_defaults()->always_capture_default();
  app.add_option("scene", o.scene, "scene file (.gltf, .glb, .obj)")->required();
  app.add_option("-o,--out", o.out, "bake folder (default: <scene without extension>.bake)");
  app.add_option("--texel-size", o.texelSize,
                 "texel edge on the surface, metres, where extras.bounce.lightmapScale is 1 "
                 "(default 0: 5 cm, finer on a small scene so it still gets 16384 texels; "
                 "docs/lightmap_atlas.md)")
      ->check(CLI::PositiveNumber);
  app.add_option("--texel-budget", o.texelBudget,
                 "texels the static surface should cover, instead of the default rule (0: the "
                 "rule; ignored with --texel-size)")
      ->check(CLI::Range(16, 1 << 26) | CLI::IsMember({0}));
  app.add_option("--max-texels", o.maxTexels,
                 "cap on the texels the static surface takes: beyond it the texels grow, with a "
                 "note")
      ->check(CLI::Range(int64_t{16}, int64_t{1} << 28));
  app.add_option("--spp", o.spp, "most samples per texel")->check(CLI::Range(16, 1 << 24));
  app.add_option("--target-error", o.targetError,
                 "sample a texel until its relative standard error is below this (0: always "
                 "--spp)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-depth", o.maxDepth, "most diffuse reflections along a path")
      ->check(CLI::Range(0, 100000));
  app.add_option("--seed", o.seed, "sampler seed (the same seed gives the same lightmap)");
  app.add_option("--threads", o.threads, "worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--backend", o.backend, "ray kernel")->check(CLI::IsMember({"embree", "bvh"}));
  app.add_option("--denoise", o.denoise, "edge-aware denoiser (guided by normal, position, chart)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--png", o.png,
                 "also write a tone-mapped picture of the lightmap (E/pi, a white surface's "
                 "radiance) to look at");
  app.add_option("--exposure", o.exposure, "PNG exposure in EV");
  app.add_option("--vpls", o.vpls,
                 "most virtual point lights (0: none; fewer when --vpl-error is met first)")
      ->check(CLI::Range(0, 1 << 24));
  app.add_option("--vpl-error", o.vplError,
                 "stop tracing VPL light paths once the total VPL flux has this relative "
                 "standard error (after at least 1024 paths)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--progress", o.progress, "draw the progress line even when stderr is no terminal");
  app.add_flag("--quiet", o.quiet, "no progress line (the summary line is still printed)");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-bake: error: %s\n", e.what());
    return 1;
  }
}
