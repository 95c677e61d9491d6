// bounce-trace: the reference path tracer's command line. Renders a scene camera's view in
// linear radiance W/(sr·m²) (EXR) and, when asked, a tone-mapped PNG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/instance_move_option.h"
#include "cli/shared_options.h"
#include "image/image_io.h"
#include "ray/ray_kernel.h"
#include "scene/framing.h"
#include "scene/instance_move.h"
#include "scene/load.h"
#include "scene/world_geometry.h"
#include "trace/camera_render.h"
#include "trace/path_tracer.h"
#include "trace/progress_line.h"
#include "trace/sampling.h"

namespace {

// Largest image side in pixels, given or derived.
constexpr int kMaxSide = bounce::kMaxImageSide;

struct Options {
  bounce::SharedOptions shared;  // scene, camera, size, exposure, path tracing
  int spp = 256;
  bool directOnly = false;
  bool indirectOnly = false;
  std::filesystem::path out;
  std::filesystem::path png;
  std::filesystem::path stdError;
  float clamp = 0.0f;
  bool progress = false;
  bool quiet = false;
  std::vector<std::string> moves;  // NAME X Y Z, repeated
};

// Default size: 512 rows, width from the camera's aspect ratio when it has one. A side derived
// from an extreme aspect is clamped to 1..kMaxSide (the --width/--height range), with a warning.
std::pair<int, int> imageSize(const Options& o, const bounce::Camera& camera) {
  int width = o.shared.width, height = o.shared.height;
  const double aspect = camera.aspect > 0.0f ? static_cast<double>(camera.aspect) : 1.0;
  if (width <= 0 && height <= 0) height = 512;
  bool clamped = false;
  const auto derivedSide = [&clamped](double side) {
    const double bounded = std::clamp(side, 1.0, static_cast<double>(kMaxSide));
    if (!(side >= 0.5 && side < kMaxSide + 0.5)) clamped = true;  // rounds outside the range
    return static_cast<int>(std::lround(bounded));
  };
  if (height <= 0) height = derivedSide(width / aspect);
  if (width <= 0) width = derivedSide(height * aspect);
  if (clamped) {
    std::fprintf(stderr,
                 "bounce-trace: warning: camera '%s' has aspect ratio %g: image size clamped to "
                 "%dx%d (each side 1..%d; give --width and --height to choose)\n",
                 camera.name.c_str(), aspect, width, height, kMaxSide);
  }
  return {width, height};
}

int run(const Options& o) {
  const std::filesystem::path scenePath = o.shared.scene;
  bounce::Scene scene = bounce::loadScene(scenePath);
  bounce::moveInstances(scene, bounce::parseInstanceMoves(o.moves));
  for (const std::string& warning : scene.warnings)
    std::fprintf(stderr, "bounce-trace: warning: %s\n", warning.c_str());
  // Without a camera in the file, frame the scene as bounce-render does (square unless the
  // image size is given).
  const float imageAspect =
      o.shared.width > 0 && o.shared.height > 0
          ? static_cast<float>(o.shared.width) / static_cast<float>(o.shared.height)
          : 1.0f;
  bool framed = false;
  const bounce::Camera camera = bounce::pickCamera(scene, o.shared.camera, imageAspect, &framed);
  if (framed)
    std::fprintf(stderr, "bounce-trace: warning: %s has no camera; framing its bounding box\n",
                 scenePath.c_str());
  const auto [width, height] = imageSize(o, camera);

  bounce::TraceSettings settings;
  settings.spp = o.spp;
  settings.maxDepth = o.shared.maxDepth;
  settings.paths = o.directOnly     ? bounce::PathSet::DirectOnly
                   : o.indirectOnly ? bounce::PathSet::IndirectOnly
                                    : bounce::PathSet::All;
  settings.seed = o.shared.seed;
  settings.threads = o.shared.threads;
  settings.backend = bounce::parseRayBackend(o.shared.backend);
  settings.lightChoice = *bounce::parseLightChoice(o.shared.lightChoice);  // checked by CLI11
  settings.clampRadiance = o.clamp;
  settings.progress = !o.quiet && (o.progress || bounce::stderrIsTerminal());

  const bounce::WorldGeometry geometry = bounce::flatten(scene);
  const auto kernel = bounce::makeRayKernel(geometry, settings.backend);
  {
    const bounce::PathTracer probe(scene, geometry, *kernel, settings);
    if (!probe.hasLights()) {
      std::fprintf(stderr,
                   "bounce-trace: warning: %s has no lights and no emissive surfaces: "
                   "the image is black\n",
                   scenePath.string().c_str());
    }
  }
  const bounce::CameraRender render =
      bounce::traceCamera(scene, geometry, *kernel, camera, width, height, settings);
  if (!render.radiance.allFinite()) {
    throw std::runtime_error("the render has non-finite pixels (a bug: please report)");
  }
  // Standard error of each pixel's mean, sqrt(s²/spp), from the per-pixel sample variance
  // (an overestimate for the scrambled Sobol sampler, which beats independent sampling).
  bounce::Image stdError(width, height);
  double meanSum = 0.0, errorSum = 0.0;
  for (std::size_t i = 0; i < stdError.pixels.size(); ++i) {
    stdError.pixels[i] =
        glm::sqrt(render.sampleVariance.pixels[i] / static_cast<float>(settings.spp));
    meanSum += static_cast<double>(bounce::luminance(render.radiance.pixels[i]));
    errorSum += static_cast<double>(bounce::luminance(stdError.pixels[i]));
  }
  // All outputs or none (image_io.h): a failing one leaves no other one behind.
  std::vector<bounce::ImageOutput> outputs{{o.out, &render.radiance, 0.0f}};
  if (!o.png.empty()) outputs.push_back({o.png, &render.radiance, o.shared.exposure});
  if (!o.stdError.empty()) outputs.push_back({o.stdError, &stdError, 0.0f});
  bounce::writeImages(outputs);
  std::fprintf(
      stderr,
      "bounce-trace: %s camera '%s' %dx%d, %d spp, max depth %d: %.1f Msamples in "
      "%.2f s (%.3f Msamples/s, %d threads, %s), standard error %.2f%% of the mean, %llu "
      "non-finite samples -> %s\n",
      scenePath.filename().string().c_str(), camera.name.c_str(), width, height, settings.spp,
      settings.maxDepth, static_cast<double>(render.samples) * 1e-6, render.seconds,
      render.seconds > 0.0 ? static_cast<double>(render.samples) * 1e-6 / render.seconds : 0.0,
      render.threads, kernel->name(), meanSum > 0.0 ? 100.0 * errorSum / meanSum : 0.0,
      static_cast<unsigned long long>(render.nonFiniteSamples), o.out.string().c_str());
  if (render.nonFiniteSamples > 0) {
    std::fprintf(stderr,
                 "bounce-trace: warning: %llu of %llu samples were non-finite (NaN or infinite "
                 "scene data in %s?) and counted as black: the affected pixels are biased low\n",
                 static_cast<unsigned long long>(render.nonFiniteSamples),
                 static_cast<unsigned long long>(render.samples), scenePath.string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "bounce-trace: path-traced reference image of a scene camera, in linear radiance "
      "W/(sr·m²) (EXR), optionally tone-mapped to PNG."};
  Options o;
  bounce::SharedOptions& shared = o.shared;
  shared.lightChoice = bounce::lightChoiceName(bounce::TraceSettings{}.lightChoice);
  shared.maxDepth = bounce::TraceSettings{}.maxDepth;
  bounce::addSceneOption(app, shared);
  bounce::addCameraOption(app, shared);
  app.add_option("--spp", o.spp, "samples per pixel")->check(CLI::Range(1, 1 << 24));
  auto* direct = app.add_flag("--direct-only", o.directOnly,
                              "only emitters seen directly and light after one reflection");
  app.add_flag("--indirect-only", o.indirectOnly, "only light after two or more reflections")
      ->excludes(direct);
  bounce::addPathTracingOptions(app, shared);
  bounce::addSizeOptions(app, shared, 1, "image",
                         "default: 512 rows, the width from the camera's aspect ratio");
  // The extension says the format: a .png name never receives EXR data.
  auto extension = [](const char* wanted) {
    return [wanted](const std::string& path) -> std::string {
      return std::filesystem::path(path).extension() == wanted
                 ? ""
                 : path + ": the file must end in " + wanted;
    };
  };
  app.add_option("--out", o.out, "output EXR, linear radiance W/(sr·m²)")
      ->required()
      ->check(extension(".exr"));
  app.add_option("--png", o.png, "also write a tone-mapped sRGB PNG")->check(extension(".png"));
  app.add_option("--std-error", o.stdError,
                 "also write each pixel's standard error sqrt(variance/spp), W/(sr·m²), as EXR")
      ->check(extension(".exr"));
  bounce::addExposureOption(app, shared);
  app.add_option("--clamp", o.clamp,
                 "firefly clamp: largest channel of a sample's reflected radiance, W/(sr·m²) "
                 "(biased; off by default)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--progress", o.progress, "draw the progress line even when stderr is no terminal");
  app.add_flag("--quiet", o.quiet, "no progress line (the summary line is still printed)");
  bounce::addMoveOption(app, o.moves);
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-trace: error: %s\n", e.what());
    return 1;
  }
}
