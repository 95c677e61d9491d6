// bounce-render: renders a scene offscreen with the forward renderer and writes linear-radiance
// EXR and/or tone-mapped sRGB PNG files. Thin: flags -> library -> files; errors -> exit 1.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "bake_folder/bake_search.h"
#include "cli/instance_move_option.h"
#include "cli/shared_options.h"
#include "gl/context.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "image/image_io.h"
#include "render/area_shadow_budget.h"
#include "render/cost_view.h"
#include "render/forward_renderer.h"
#include "render/gpu_scene.h"
#include "render/punctual_shadow_budget.h"
#include "render/view.h"
#include "render/vpl_pass.h"
#include "scene/framing.h"
#include "scene/instance_move.h"
#include "scene/load.h"
#include "vpl/vpl_retrace.h"

namespace {

struct Options {
  bounce::SharedOptions shared;  // scene, camera, size, exposure, bake, mode, msaa, cost view
  std::vector<std::string> outputs;
  std::string context;
  int frames = 1;
  bool noShadows = false;
  int shadowResolution = 0;
  std::string shadowFilter = "poisson";
  std::vector<std::string> moves;  // NAME X Y Z, repeated
  std::size_t vplGroups = bounce::kMaxVplGroups;
  bool noVplCulling = false;
  bool noProbes = false;
  bool liveStaticLights = false;
  bool noVplShadows = false;
  bool vplPerPixel = false;
  bool noLightCulling = false;
  float shadowFilterRadius = 1.5f;
  std::optional<uint64_t> vplPaths;  // draw the VPLs of the bake's first N light paths
  std::optional<float> vplClamp;     // VPL clamp distance, m (default: the bake's)
};

bounce::RendererSettings rendererSettings(const Options& options, bool hasBake) {
  bounce::RendererSettings settings;
  settings.mode = options.shared.mode.empty()
                      ? (hasBake ? bounce::RenderMode::Full : bounce::RenderMode::Direct)
                      : *bounce::parseRenderMode(options.shared.mode);  // CLI11 checked
  settings.shadows.enabled = !options.noShadows;
  settings.shadows.resolution = options.shadowResolution;
  settings.shadows.filter = options.shadowFilter == "hardware" ? bounce::ShadowFilter::Hardware
                                                               : bounce::ShadowFilter::Poisson;
  settings.shadows.filterRadius = options.shadowFilterRadius;
  settings.vpls.groups = options.vplGroups;
  settings.vpls.culling = !options.noVplCulling;
  settings.probes = !options.noProbes;
  settings.precomputedStaticDirect = !options.liveStaticLights;
  settings.vpls.shadows.enabled = !options.noVplShadows;
  settings.vpls.perVertex = !options.vplPerPixel;
  // The cut-off follows the exposure the PNG is shown at (render/light_cutoff.h).
  settings.lightCulling.enabled = !options.noLightCulling;
  settings.lightCulling.irradianceFloor =
      bounce::irradianceFloorForExposure(options.shared.exposure);
  return settings;
}

// Each pass's GPU time and the frame's CPU spans, mean and 95th percentile over the frames.
void printProfile(const bounce::FrameProfile& profile) {
  std::fprintf(stderr, "bounce-render: %-34s %7s %9s %9s\n", "GPU pass", "frames", "mean ms",
               "p95 ms");
  for (const bounce::TimeSummary& row : profile.gpuPasses())
    std::fprintf(stderr, "bounce-render:   %-32s %7zu %9.3f %9.3f\n", row.name.c_str(), row.frames,
                 row.mean, row.p95);
  std::fprintf(stderr, "bounce-render: %-34s %7s %9s %9s\n", "CPU (frame: build + submit, no wait)",
               "frames", "mean ms", "p95 ms");
  for (const bounce::TimeSummary& row : profile.cpu())
    std::fprintf(stderr, "bounce-render:   %-32s %7zu %9.3f %9.3f\n", row.name.c_str(), row.frames,
                 row.mean, row.p95);
}

// The cost mode: the counts per pixel (EXR: raw, R lights, G VPLs, B shadow-map taps; PNG: one
// count in false colour with its legend bar) and their means.
void writeCostView(const Options& options, const bounce::Image& counts) {
  const bounce::CostStats stats = bounce::costStats(counts);
  std::fprintf(stderr,
               "bounce-render: cost per pixel (mean / max over the frame, background 0%s): "
               "lights %.2f / %g, VPLs %.2f / %g, shadow-map taps %.2f / %g\n",
               options.shared.msaa > 1 ? "; means over each pixel's samples" : "", stats.meanLights,
               static_cast<double>(stats.maxLights), stats.meanVpls,
               static_cast<double>(stats.maxVpls), stats.meanShadowTaps,
               static_cast<double>(stats.maxShadowTaps));
  const bounce::CostCount count =
      *bounce::parseCostCount(options.shared.costCount);  // CLI11 checked
  const float largest = count == bounce::CostCount::Lights ? stats.maxLights
                        : count == bounce::CostCount::Vpls ? stats.maxVpls
                                                           : stats.maxShadowTaps;
  const float scaleMax = options.shared.costMax.value_or(bounce::costScaleMax(largest));
  bool png = false;
  for (const std::string& out : options.outputs) {
    if (std::filesystem::path(out).extension() == ".png") {
      bounce::writeDisplayPng(out, bounce::costFalseColour(counts, count, scaleMax));
      png = true;
    } else {
      bounce::writeExr(out, counts);
    }
    std::fprintf(stderr, "bounce-render: wrote %s\n", out.c_str());
  }
  if (png)
    std::fprintf(stderr, "bounce-render: cost view PNG: %s\n",
                 bounce::describeCostLegend(count, scaleMax).c_str());
}

using Clock = std::chrono::steady_clock;

double milliseconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// --context, else EGL where it works and OSMesa otherwise; says which one it got.
std::unique_ptr<bounce::gl::Context> openContext(const Options& options) {
  std::optional<bounce::gl::ContextBackend> backend;
  if (options.context == "osmesa") backend = bounce::gl::ContextBackend::OSMesa;
  if (options.context == "egl") backend = bounce::gl::ContextBackend::EGL;
  std::string eglFailure;
  auto context = bounce::gl::createOffscreenContext(backend, &eglFailure);
  if (!eglFailure.empty())
    std::fprintf(stderr, "bounce-render: EGL unavailable (%s); using OSMesa\n", eglFailure.c_str());
  std::fprintf(stderr, "bounce-render: context %s: OpenGL %s, %s\n",
               bounce::gl::backendName(context->backend()), context->version().c_str(),
               context->renderer().c_str());
  return context;
}

// The scene with --move applied. Refused before the minutes a million emitters take to cut and
// group: the frame could not draw them (render/gpu_scene.h).
bounce::Scene loadRenderScene(const Options& options) {
  bounce::Scene scene = bounce::loadScene(options.shared.scene, bounce::GpuScene::sceneLimits());
  bounce::moveInstances(scene, bounce::parseInstanceMoves(options.moves));
  for (const std::string& warning : scene.warnings)
    std::fprintf(stderr, "bounce-render: warning: %s\n", warning.c_str());
  return scene;
}

bounce::Camera renderCamera(const Options& options, const bounce::Scene& scene) {
  const float aspect =
      static_cast<float>(options.shared.width) / static_cast<float>(options.shared.height);
  bool framed = false;
  bounce::Camera camera = bounce::pickCamera(scene, options.shared.camera, aspect, &framed);
  if (framed)
    std::fprintf(stderr, "bounce-render: warning: %s has no camera; framing its bounding box\n",
                 options.shared.scene.c_str());
  return camera;
}

// The bake in use and the folder it came from: --bake, else the one found for the scene
// (bake_folder/bake_search.h), unless --no-bake.
struct FoundBake {
  std::optional<bounce::Bake> bake;
  std::string dir;
};

FoundBake findBake(const Options& options, const bounce::Scene& scene) {
  FoundBake found{std::nullopt, options.shared.bake};
  if (!options.shared.bake.empty()) {
    found.bake = bounce::readBake(options.shared.bake, scene);
  } else if (!options.shared.noBake) {
    bounce::BakeSearch search =
        bounce::findSceneBake(options.shared.scene, scene, bounce::toolDirectory());
    for (const std::string& note : search.notes)
      std::fprintf(stderr, "bounce-render: %s\n", note.c_str());
    found.bake = std::move(search.bake);
    found.dir = search.dir.string();
  }
  if (found.bake)
    std::fprintf(stderr, "bounce-render: bake %s: lightmap %dx%d, %zu static instances\n",
                 found.dir.c_str(), found.bake->layout.width, found.bake->layout.height,
                 found.bake->layout.instances.size());
  return found;
}

// The renderer's settings for this bake; refuses a mode that draws baked light without one.
bounce::RendererSettings checkedSettings(const Options& options, const bounce::Scene& scene,
                                         const FoundBake& found) {
  bounce::RendererSettings settings = rendererSettings(options, found.bake.has_value());
  if (bounce::renderModeNeedsBake(settings.mode) && !found.bake)
    throw std::runtime_error("--mode " + std::string(bounce::renderModeName(settings.mode)) +
                             " draws baked light: give --bake DIR" +
                             (options.shared.noBake ? " (and no --no-bake)" : ""));
  // The bake's count rule over the scene with its dynamic instances placed (--move).
  if (found.bake && found.bake->vpls && options.shared.dynamicVpls == "retrace")
    settings.vplTracer = bounce::placedVplTracer(scene, *found.bake);
  if (settings.mode == bounce::RenderMode::Lightmap)
    std::fprintf(stderr,
                 "bounce-render: mode lightmap: pixels are E/pi W/(sr·m²), the radiance of a "
                 "white (rho = 1) Lambertian surface under the baked irradiance E (W/m²)\n");
  return settings;
}

// --vpl-paths and --vpl-clamp: which of the bake's VPLs are drawn, at which clamp distance.
void selectVpls(const Options& options, bounce::ForwardRenderer& renderer, const FoundBake& found) {
  if (!options.vplPaths && !options.vplClamp) return;
  if (!renderer.hasVpls())
    throw std::runtime_error(
        "--vpl-paths and --vpl-clamp choose among the bake's VPLs, but " +
        (found.bake ? "the bake " + found.dir + " has none" : std::string("no bake is used")));
  const bounce::ForwardRenderer::VplSelection bakes = renderer.vplSelection();
  renderer.setVplSelection(options.vplPaths.value_or(bakes.totalPaths),
                           options.vplClamp.value_or(bakes.bakeClampDistance));
  const bounce::ForwardRenderer::VplSelection drawn = renderer.vplSelection();
  std::fprintf(stderr,
               "bounce-render: VPLs of %llu of the bake's %llu light paths (%zu VPLs, flux x "
               "%.4g), clamp r = %.4g m (the bake's %.4g m)\n",
               static_cast<unsigned long long>(drawn.paths),
               static_cast<unsigned long long>(drawn.totalPaths), drawn.vplCount,
               static_cast<double>(drawn.totalPaths) / static_cast<double>(drawn.paths),
               static_cast<double>(drawn.clampDistance),
               static_cast<double>(drawn.bakeClampDistance));
}

// The light lists per cluster and which lights got a shadow map or cube.
void reportLights(const bounce::ForwardRenderer& renderer, const bounce::Scene& scene) {
  const bounce::LightGridStats grid = renderer.lightGridStats();
  if (grid.clusters > 0)
    std::fprintf(stderr,
                 "bounce-render: light culling: %d clusters, %.2f punctual and %.2f area lights "
                 "per cluster (at most %zu and %zu), floor %.3g W/m^2\n",
                 grid.clusters, static_cast<double>(grid.punctualEntries) / grid.clusters,
                 static_cast<double>(grid.areaEntries) / grid.clusters, grid.maxPunctual,
                 grid.maxArea,
                 static_cast<double>(renderer.settings().lightCulling.irradianceFloor));
  if (std::count(renderer.punctualShadowSlots().begin(), renderer.punctualShadowSlots().end(), -1) >
      0)
    std::fprintf(
        stderr, "bounce-render: %s\n",
        bounce::describePunctualShadowMaps(scene.lights, renderer.punctualShadowSlots()).c_str());
  if (renderer.areaShadowSlots() > 0)
    std::fprintf(
        stderr, "bounce-render: %s\n",
        bounce::describeAreaShadowChoice(renderer.areaShadowChoice(), renderer.areaShadowSlots())
            .c_str());
}

// --frames N: the same frame again into the same target, read back each time; where the time
// goes, pass by pass (the first frame, with the driver's shader JIT, left out).
void benchmarkFrames(const Options& options, bounce::ForwardRenderer& renderer,
                     const bounce::Camera& camera) {
  if (options.frames <= 1) return;
  bounce::gl::RenderTarget target(options.shared.width, options.shared.height, options.shared.msaa);
  // One frame into this target first: llvmpipe compiles shader variants for it lazily.
  renderer.render(camera, target);
  (void)renderer.readBack(target);
  renderer.clearProfile();
  const auto repeatStart = Clock::now();
  for (int i = 1; i < options.frames; ++i) {
    renderer.render(camera, target);
    (void)renderer.readBack(target);
  }
  std::fprintf(stderr, "bounce-render: %d more frames: %.2f ms per frame (render + readback)\n",
               options.frames - 1, milliseconds(repeatStart, Clock::now()) / (options.frames - 1));
  printProfile(renderer.profile(true));
}

// The VPLs traced again around the dynamic instances, and the share of VPL irradiance the clamp
// removed over the frame.
void reportVpls(const Options& options, bounce::ForwardRenderer& renderer,
                const bounce::Scene& scene, const FoundBake& found, const bounce::Camera& camera) {
  const bool dynamicInstances = std::any_of(
      scene.instances.begin(), scene.instances.end(),
      [](const bounce::Instance& i) { return i.mobility == bounce::Mobility::Dynamic; });
  if (renderer.settings().vplTracer && dynamicInstances)
    std::fprintf(stderr,
                 "bounce-render: VPLs traced again with the dynamic instances in place: %zu "
                 "(bake: %zu)\n",
                 renderer.vpls().groups().vplCount(), found.bake->vpls->size());
  if (!renderer.hasVpls() ||
      !(bounce::renderModeNeedsVpls(renderer.settings().mode) || dynamicInstances))
    return;
  const bounce::VplClampReport clamp =
      renderer.measureVplClamp(camera, options.shared.width, options.shared.height);
  std::fprintf(stderr,
               "bounce-render: VPL clamp removed %.2f%% of the VPL irradiance over the frame "
               "(%zu VPLs in %zu groups, r = %.4g m; every visible surface, luminance)\n",
               100.0 * clamp.removedFraction(), clamp.vplCount,
               renderer.vpls().groups().groupCount(), static_cast<double>(clamp.clampDistance));
}

// All outputs or none (image_io.h): a failing --out leaves no other one behind.
void writeFrame(const Options& options, const bounce::Image& image) {
  std::vector<bounce::ImageOutput> outputs;
  for (const std::string& out : options.outputs)
    outputs.push_back({out, &image, options.shared.exposure});
  bounce::writeImages(outputs);
  for (const std::string& out : options.outputs)
    std::fprintf(stderr, "bounce-render: wrote %s\n", out.c_str());
}

int run(const Options& options) {
  const auto context = openContext(options);
  bounce::Scene scene = loadRenderScene(options);
  const bounce::Camera camera = renderCamera(options, scene);
  const auto start = Clock::now();
  const FoundBake found = findBake(options, scene);
  const bounce::RendererSettings settings = checkedSettings(options, scene, found);
  bounce::ForwardRenderer renderer(scene, bounce::gl::shaderDirectory(), settings,
                                   found.bake ? &*found.bake : nullptr);
  for (const std::string& warning : renderer.warnings())
    std::fprintf(stderr, "bounce-render: warning: %s\n", warning.c_str());
  selectVpls(options, renderer, found);
  const auto uploaded = Clock::now();
  const bounce::Image image = renderer.renderImage(camera, options.shared.width,
                                                   options.shared.height, options.shared.msaa);
  const auto rendered = Clock::now();
  std::fprintf(stderr,
               "bounce-render: %dx%d, camera '%s', %zu triangles: set-up %.1f ms, first frame "
               "%.1f ms (render + readback, includes the driver's shader JIT), mode %s, msaa %d\n",
               options.shared.width, options.shared.height, camera.name.c_str(),
               scene.triangleCount(), milliseconds(start, uploaded),
               milliseconds(uploaded, rendered),
               std::string(bounce::renderModeName(settings.mode)).c_str(), options.shared.msaa);
  reportLights(renderer, scene);
  benchmarkFrames(options, renderer, camera);
  reportVpls(options, renderer, scene, found, camera);
  if (settings.mode == bounce::RenderMode::Cost)
    writeCostView(options, image);
  else
    writeFrame(options, image);
  return 0;
}

// --out (repeatable), --context and --frames: where the frame goes and how it is timed.
void addOutputOptions(CLI::App& app, Options& options) {
  app.add_option("--out", options.outputs,
                 "output file, .exr (linear) or .png (tone-mapped); "
                 "repeatable")
      ->required()
      ->check([](const std::string& path) -> std::string {
        const auto ext = std::filesystem::path(path).extension();
        return ext == ".png" || ext == ".exr" ? "" : path + ": the file must end in .png or .exr";
      });
  app.add_option("--context", options.context, "osmesa or egl (default: EGL if it works)")
      ->check(CLI::IsMember({"osmesa", "egl"}));
  app.add_option("--frames", options.frames,
                 "render the frame this many times and report the mean time and, per pass, the GPU "
                 "time (mean and 95th percentile), the frame's CPU time (building and "
                 "submitting it), the wait for the GPU and the readback (benchmark)")
      ->check(CLI::Range(1, 100000));
}

// The VPLs drawn: groups, light paths, clamp, culling, probes and shadow cubes.
void addVplOptions(CLI::App& app, Options& options) {
  app.add_option("--vpl-groups", options.vplGroups,
                 "coarse VPL groups K (representatives, per-cell lightcuts; default 64)")
      ->check(CLI::Range(std::size_t{1}, bounce::kMaxVplGroups));
  app.add_option("--vpl-paths", options.vplPaths,
                 "draw the VPLs of the bake's first N light paths only, each flux x (the bake's "
                 "paths)/N: the same estimate from fewer VPLs (default: all)")
      ->check(CLI::PositiveNumber);
  app.add_option("--vpl-clamp", options.vplClamp,
                 "VPL clamp distance r in metres: the geometry term is capped at 1/r^2; 0 "
                 "unclamped (default: the bake's)")
      ->check(CLI::Range(0.0f, 1e6f));
  app.add_flag("--no-probes", options.noProbes,
               "light the static instances without a lightmap region from the VPLs, as before "
               "the bake's irradiance probes (for comparison)");
  app.add_flag("--live-static-lights", options.liveStaticLights,
               "evaluate the static lights at every static pixel, as before their direct light "
               "was computed per lightmap texel and probe-lit corner at load (for comparison)");
  app.add_flag("--no-vpl-culling", options.noVplCulling,
               "evaluate every VPL at every pixel (no per-cell lightcuts)");
  app.add_flag("--no-light-culling", options.noLightCulling,
               "shade every light at every pixel (no per-cluster light lists; by default a "
               "light is left out where it gives less irradiance than half an 8-bit code value "
               "at --exposure)");
  app.add_flag("--vpl-per-pixel", options.vplPerPixel,
               "let every pixel of a dynamic instance gather the VPLs itself, instead of "
               "interpolating them gathered at its vertices (for comparison)");
  app.add_flag("--no-vpl-shadows", options.noVplShadows,
               "draw every VPL unoccluded (no shadow cubes for the VPL groups' parts)");
}

// The shadow maps: on or off, resolution, filter.
void addShadowOptions(CLI::App& app, Options& options) {
  app.add_flag("--no-shadows", options.noShadows,
               "draw every light unshadowed (punctual and area lights)");
  app.add_option("--shadow-resolution", options.shadowResolution,
                 "texels per side of every shadow map / cube face (default: chosen per light)")
      ->check(CLI::Range(16, 16384));
  app.add_option(
         "--shadow-filter", options.shadowFilter,
         "hardware (hard: one 2x2 comparison tap; area lights from their centre) or poisson "
         "(soft, default: 16 rotated taps; area lights: percentage-closer soft shadows)")
      ->check(CLI::IsMember({"hardware", "poisson"}));
  app.add_option("--shadow-filter-radius", options.shadowFilterRadius,
                 "Poisson kernel radius in shadow-map texels (default 1.5)")
      ->check(CLI::Range(0.0f, 64.0f));
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Render a scene with the forward renderer (direct light with shadow maps) into "
      "linear-radiance "
      "EXR (W/(sr·m²)) and/or tone-mapped sRGB PNG files.",
      "bounce-render"};
  bounce::SharedOptions& shared = options.shared;
  shared.width = 512;
  shared.height = 512;
  bounce::addSceneOption(app, shared);
  bounce::addCameraOption(app, shared);
  bounce::addSizeOptions(app, shared, 1, "image", "default 512");
  addOutputOptions(app, options);
  bounce::addExposureOption(app, shared);
  bounce::addBakeOptions(app, shared);
  bounce::addMsaaOption(app, shared);
  bounce::addModeOption(app, shared, bounce::renderModeNames(), "what to draw");
  addVplOptions(app, options);
  bounce::addDynamicVplsOption(app, shared);
  addShadowOptions(app, options);
  bounce::addCostViewOptions(app, shared, "1, 2 or 5 x 10^k at or above the frame's largest count");
  bounce::addMoveOption(app, options.moves);
  CLI11_PARSE(app, argc, argv);
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-render: error: %s\n", e.what());
    return 1;
  }
}
