// Where a frame's time goes, per content scene (docs/renderer.md, "Frame cost"): the full frame
// and the lightmap-only frame (--mode lightmap) rendered --frames times at --width x --height,
// their ratio, each pass's GPU time (ForwardRenderer::profile, pass timers), the CPU time of
// building and submitting the frame, and the cost view's counts (mean lights, VPLs and shadow-map
// taps per pixel, RenderMode::Cost), and the full frame's CPU time with a moving camera (turned
// 0.25° and moved 1 cm along its view each frame: what a walking viewer costs the caches). Run by
// hand; a tiny smoke run is registered with CTest.
//
//   bench_frame_cost SCENE[=BAKE_DIR|=none]... [--width W] [--height H] [--frames N] [--msaa S]
//                    [--live-static-lights] [--vpl-per-pixel]
//
// BAKE_DIR: the scene's bake; none: no bake (full is then the direct frame and the lightmap
// frame is not drawn); nothing: SCENE.bake beside the scene or the build step's bake.
#include <CLI/CLI.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "bake_folder/bake_search.h"
#include "gl/context.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "render/cost_view.h"
#include "render/forward_renderer.h"
#include "scene/framing.h"
#include "scene/load.h"

namespace {

struct Options {
  std::vector<std::string> scenes;
  int width = 480, height = 270, frames = 10, msaa = 1;
  bool liveStaticLights = false;  // RendererSettings::precomputedStaticDirect off
  bool vplPerPixel = false;       // VplRenderSettings::perVertex off
};

struct FrameTimes {
  double gpuTotal = 0.0;  // Σ of the passes' mean GPU times, ms
  double cpuFrame = 0.0;  // mean CPU time of render(), ms
  double cpuFrameP95 = 0.0;
  std::vector<bounce::TimeSummary> passes;
};

// The camera of frame `i` when it moves: turned about its up axis by 0.25° a frame and moved
// 1 cm a frame along its view (a slow walk: 15°/s and 0.6 m/s at 60 frames a second).
bounce::Camera movedCamera(const bounce::Camera& camera, int i) {
  bounce::Camera moved = camera;
  const glm::vec3 position = camera.position();
  const glm::mat4 turn =
      glm::rotate(glm::mat4(1.0f), glm::radians(0.25f * static_cast<float>(i)), camera.up());
  moved.cameraToWorld = turn * camera.cameraToWorld;  // the rotation; the position follows
  moved.cameraToWorld[3] =
      glm::vec4(position + 0.01f * static_cast<float>(i) * camera.forward(), 1);
  return moved;
}

// `frames` frames of `mode` after one warm-up frame (llvmpipe compiles variants lazily); the
// camera still or moving.
FrameTimes measure(bounce::ForwardRenderer& renderer, const bounce::Camera& camera,
                   bounce::RenderMode mode, const Options& options, bool moving = false) {
  renderer.setMode(mode);
  bounce::gl::RenderTarget target(options.width, options.height, options.msaa);
  renderer.render(camera, target);
  (void)renderer.readBack(target);
  renderer.clearProfile();
  for (int i = 0; i < options.frames; ++i) {
    renderer.render(moving ? movedCamera(camera, i + 1) : camera, target);
    (void)renderer.readBack(target);
  }
  FrameTimes times;
  const bounce::FrameProfile& profile = renderer.profile(true);
  times.passes = profile.gpuPasses();
  for (const bounce::TimeSummary& pass : times.passes) times.gpuTotal += pass.mean;
  for (const bounce::TimeSummary& cpu : profile.cpu())
    if (cpu.name == "frame") {
      times.cpuFrame = cpu.mean;
      times.cpuFrameP95 = cpu.p95;
    }
  return times;
}

void benchScene(const std::string& argument, const Options& options) {
  const std::size_t equals = argument.find('=');
  const std::string path = argument.substr(0, equals);
  const std::optional<std::string> bakeArg =
      equals == std::string::npos ? std::nullopt : std::optional(argument.substr(equals + 1));
  const bounce::Scene scene = bounce::loadScene(path);
  std::optional<bounce::Bake> bake;
  if (bakeArg && *bakeArg != "none") bake = bounce::readBake(*bakeArg, scene);
  if (!bakeArg) bake = bounce::findSceneBake(path, scene, bounce::toolDirectory()).bake;
  const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
  const bounce::Camera camera = bounce::pickCamera(scene, "", aspect, nullptr);
  bounce::RendererSettings settings;
  settings.mode = bake ? bounce::RenderMode::Full : bounce::RenderMode::Direct;
  settings.precomputedStaticDirect = !options.liveStaticLights;
  settings.vpls.perVertex = !options.vplPerPixel;
  bounce::ForwardRenderer renderer(scene, bounce::gl::shaderDirectory(), settings,
                                   bake ? &*bake : nullptr);
  const FrameTimes full = measure(renderer, camera, settings.mode, options);
  std::optional<FrameTimes> lightmap;
  if (bake) lightmap = measure(renderer, camera, bounce::RenderMode::Lightmap, options);
  const FrameTimes moving = measure(renderer, camera, settings.mode, options, true);
  renderer.setMode(bounce::RenderMode::Cost);
  const bounce::CostStats cost =
      bounce::costStats(renderer.renderImage(camera, options.width, options.height, 1));
  std::printf("| %s | %s | %.2f | %.2f / %.2f | %.2f / %.2f | %s | %s | %.2f | %.1f | %.1f |\n",
              path.c_str(), bake ? "yes" : "no", full.gpuTotal, full.cpuFrame, full.cpuFrameP95,
              moving.cpuFrame, moving.cpuFrameP95,
              lightmap ? (std::to_string(lightmap->gpuTotal).substr(0, 6)).c_str() : "-",
              lightmap && lightmap->gpuTotal > 0.0
                  ? (std::to_string(full.gpuTotal / lightmap->gpuTotal).substr(0, 5)).c_str()
                  : "-",
              cost.meanLights, cost.meanVpls, cost.meanShadowTaps);
  std::string passes;
  for (const bounce::TimeSummary& pass : full.passes) {
    char cell[96];
    std::snprintf(cell, sizeof cell, "%s%s %.2f/%.2f", passes.empty() ? "" : "; ",
                  pass.name.c_str(), pass.mean, pass.p95);
    passes += cell;
  }
  std::fprintf(stderr, "bench_frame_cost: %s full frame GPU passes, mean/p95 ms: %s\n",
               path.c_str(), passes.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Frame cost per scene: full vs lightmap-only frame, GPU passes, cost counts",
               "bench_frame_cost"};
  app.add_option("scenes", options.scenes, "SCENE[=BAKE_DIR|=none] ...")->required();
  app.add_option("--width", options.width, "pixels")->check(CLI::Range(1, 8192));
  app.add_option("--height", options.height, "pixels")->check(CLI::Range(1, 8192));
  app.add_option("--frames", options.frames, "frames measured per mode")
      ->check(CLI::Range(1, 10000));
  app.add_option("--msaa", options.msaa, "samples per pixel (default 1)")->check(CLI::Range(1, 64));
  app.add_flag("--live-static-lights", options.liveStaticLights,
               "evaluate the static area lights per pixel on static surfaces (not from the "
               "texels and corners computed at load), as bounce-render --live-static-lights");
  app.add_flag("--vpl-per-pixel", options.vplPerPixel,
               "every pixel of a dynamic instance gathers the VPLs (not from its vertices), as "
               "bounce-render --vpl-per-pixel");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto context = bounce::gl::createOffscreenContext(std::nullopt, nullptr);
    std::fprintf(stderr, "bench_frame_cost: %s, %dx%d, %d frames per mode, msaa %d\n",
                 context->renderer().c_str(), options.width, options.height, options.frames,
                 options.msaa);
    std::printf(
        "| scene | bake | full GPU ms | full CPU ms still, mean / p95 | moving | lightmap GPU ms "
        "| full / lightmap | lights/px | VPLs/px | taps/px |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& scene : options.scenes) benchScene(scene, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_frame_cost: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
