// bounce-bake: bakes a scene's lightmap (irradiance E in W/m² per texel of the atlas) and writes
// the bake folder (engine/bake/bake_folder.h): lightmap.exr, layout.bin, bake.json, and the
// virtual point lights (vpls, baker/vpl) unless --vpls 0.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "image/image_io.h"
#include "pipeline/bake_memory.h"
#include "pipeline/scene_bake.h"
#include "scene/load.h"
#include "trace/progress_line.h"
#include "trace/sampling.h"

namespace {

const bounce::SceneBakeSettings kDefaults;

struct Options {
  std::filesystem::path scene;
  std::filesystem::path out;
  bounce::SceneBakeSettings bake;
  std::string backend = "embree";
  std::string denoise = kDefaults.denoise ? "on" : "off";
  std::string maxMemory;  // "512M", "4G"; empty: no limit
  std::filesystem::path png;
  float exposure = 0.0f;
  bool progress = false;
  bool quiet = false;
};

// Set by SIGINT/SIGTERM: the bake stops at its next check and nothing is written.
volatile std::sig_atomic_t interrupted = 0;
extern "C" void onInterrupt(int) {
  interrupted = 1;
}

// The progress line on stderr ("[4/8] irradiance 45.1%  2.31 Msamples/s  ETA 12 s"), rewritten
// in place; cancels when interrupted.
class ProgressLineObserver final : public bounce::BakeObserver {
 public:
  explicit ProgressLineObserver(bool draw) : draw_(draw) {}
  bool onProgress(const bounce::BakeProgress& p) override {
    if (draw_) {
      const double percent =
          p.total > 0 ? 100.0 * static_cast<double>(p.done) / static_cast<double>(p.total) : 100.0;
      std::fprintf(stderr, "\rbounce-bake: [%d/%d] %-24s %5.1f%%", p.stage, p.stages,
                   p.name.c_str(), percent);
      if (p.samplesPerSecond > 0.0)
        std::fprintf(stderr, "  %.2f Msamples/s", p.samplesPerSecond * 1e-6);
      std::fprintf(stderr, p.finished ? "  %.1f s        \n" : "  ETA %.0f s        ",
                   p.finished ? p.seconds : p.etaSeconds);
      std::fflush(stderr);
    }
    return interrupted == 0;
  }

 private:
  bool draw_;
};

int run(Options o) {
  const auto start = std::chrono::steady_clock::now();
  const bounce::Scene scene = bounce::loadScene(o.scene);
  for (const std::string& warning : scene.warnings)
    std::fprintf(stderr, "bounce-bake: warning: %s\n", warning.c_str());
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.bake.backend = bounce::parseRayBackend(o.backend);
  o.bake.denoise = o.denoise == "on";
  if (!o.maxMemory.empty()) o.bake.maxMemory = bounce::parseMemorySize(o.maxMemory);
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  ProgressLineObserver observer(!o.quiet && (o.progress || bounce::stderrIsTerminal()));
  const std::filesystem::path out =
      o.out.empty() ? std::filesystem::path(o.scene).replace_extension(".bake") : o.out;
  bounce::SceneBake baked;
  try {
    baked = bounce::bakeScene(scene, o.bake, &observer);
  } catch (const bounce::BakeCancelled&) {
    std::fprintf(stderr, "\nbounce-bake: cancelled: nothing written (%s is as it was)\n",
                 out.string().c_str());
    return 130;
  }
  for (const std::string& note : baked.notes)
    std::fprintf(stderr, "bounce-bake: note: %s\n", note.c_str());
  bounce::BakeManifest::Measured& measured = baked.folder.manifest.measured;
  measured.seconds.load = loadSeconds;
  measured.seconds.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bounce::writeBake(out, baked.folder);
  if (!o.png.empty()) {
    // A white Lambertian surface's radiance E/π, tone-mapped: what the map looks like.
    bounce::Image radiance = baked.folder.irradiance;
    for (glm::vec3& p : radiance.pixels) p *= bounce::kInvPi;
    bounce::writePng(o.png, radiance, o.exposure);
  }
  const bounce::BakeManifest& manifest = baked.folder.manifest;
  const bounce::BakeManifest::Atlas& atlas = manifest.atlas;
  std::fprintf(stderr,
               "bounce-bake: %s: atlas %dx%d (%d charts, %.0f%% used, texel %.4g m), %llu "
               "texels, %.0f spp mean, estimated error mean %.2f%% p95 %.2f%%, %.2f Mrays/s, "
               "%.2f s (irradiance %.2f s), memory %s (estimated %s) -> %s\n",
               o.scene.filename().string().c_str(), atlas.width, atlas.height, atlas.charts,
               100.0 * atlas.utilisation, atlas.texelSize,
               static_cast<unsigned long long>(baked.coveredTexels), manifest.samples.perTexelMean,
               100.0 * manifest.estimatedError.mean, 100.0 * manifest.estimatedError.p95,
               measured.raysPerSecond * 1e-6, measured.seconds.total, measured.seconds.irradiance,
               bounce::formatBytes(baked.measuredPeakBytes).c_str(),
               bounce::formatBytes(baked.estimatedPeakBytes).c_str(), out.string().c_str());
  const auto nonFinite = static_cast<unsigned long long>(manifest.samples.nonFinite);
  if (nonFinite > 0)
    std::fprintf(stderr,
                 "bounce-bake: warning: %llu samples were non-finite (NaN or infinite scene data "
                 "in %s?) and counted as black: the affected texels are biased low\n",
                 nonFinite, o.scene.string().c_str());
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
  app.add_option("--texel-size", o.bake.texelSize,
                 "texel edge on the surface, metres, where extras.bounce.lightmapScale is 1 "
                 "(default 0: 5 cm, finer on a small scene so it still gets 16384 texels; "
                 "docs/lightmap_atlas.md)")
      ->check(CLI::PositiveNumber);
  app.add_option("--texel-budget", o.bake.texelBudget,
                 "texels the static surface should cover, instead of the default rule (0: the "
                 "rule; ignored with --texel-size)")
      ->check(CLI::Range(16, 1 << 26) | CLI::IsMember({0}));
  app.add_option("--max-texels", o.bake.maxTexels,
                 "cap on the texels the static surface takes: beyond it the texels grow, with a "
                 "note")
      ->check(CLI::Range(int64_t{16}, int64_t{1} << 28));
  app.add_option("--spp", o.bake.spp, "most samples per texel")->check(CLI::Range(16, 1 << 24));
  app.add_option("--target-error", o.bake.targetError,
                 "sample a texel until its relative standard error is below this (0: always "
                 "--spp)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-depth", o.bake.maxDepth, "most diffuse reflections along a path")
      ->check(CLI::Range(0, 100000));
  app.add_option("--seed", o.bake.seed, "sampler seed (the same seed gives the same lightmap)");
  app.add_option("--threads", o.bake.threads, "worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--backend", o.backend, "ray kernel")->check(CLI::IsMember({"embree", "bvh"}));
  app.add_option("--denoise", o.denoise, "edge-aware denoiser (guided by normal, position, chart)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--png", o.png,
                 "also write a tone-mapped picture of the lightmap (E/pi, a white surface's "
                 "radiance) to look at");
  app.add_option("--exposure", o.exposure, "PNG exposure in EV");
  app.add_option("--vpls", o.bake.vpls,
                 "most virtual point lights (0: none; fewer when --vpl-error is met first)")
      ->check(CLI::Range(0, 1 << 24));
  app.add_option("--vpl-error", o.bake.vplError,
                 "stop tracing VPL light paths once the total VPL flux has this relative "
                 "standard error (after at least 1024 paths)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-memory", o.maxMemory,
                 "refuse a bake whose estimated peak memory is over this (512M, 4G, ...): the "
                 "estimate is made after the atlas, before the large allocations; nothing is "
                 "written")
      ->check([](const std::string& size) -> std::string {
        try {
          bounce::parseMemorySize(size);
          return "";
        } catch (const std::exception& e) {
          return e.what();
        }
      });
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
