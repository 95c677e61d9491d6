// bounce-bake: bakes a scene's lightmap (irradiance E in W/m² per texel of the atlas) and writes
// the bake folder (engine/bake_folder/bake_folder.h): lightmap.exr, layout.bin, bake.json, and the
// virtual point lights (vpls, baker/vpl) unless --vpls 0.
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include "bake_merge.h"
#ifdef BOUNCE_HAVE_MPI
#include "bake_mpi.h"
#endif
#include "bake_folder/gather.h"
#include "bake_progress_line.h"
#include "bake_summary.h"
#include "cli/shared_options.h"
#include "image/image_io.h"
#include "pipeline/bake_memory.h"
#include "pipeline/scene_bake.h"
#include "pipeline/tile_journal.h"
#include "ray/ray_kernel.h"
#include "scene/load.h"
#include "trace/progress_line.h"
#include "trace/sampling.h"

namespace {

const bounce::SceneBakeSettings kDefaults;

struct Options {
  bounce::SharedOptions shared;  // scene, exposure, path tracing (into `bake` after the parse)
  std::filesystem::path scene;
  std::filesystem::path out;
  bounce::SceneBakeSettings bake;
  std::string denoise = kDefaults.denoise ? "on" : "off";
  std::string gather = bounce::gatherName(kDefaults.gather);
  std::string maxMemory;  // "512M", "4G"; empty: no limit
  std::filesystem::path png;
  std::string shard;  // "K/N"; empty: the whole bake
  bool resume = false;
  bool mpi = false;
  bool progress = false;
  bool quiet = false;
};

// "K/N" with 1 ≤ K ≤ N into (K − 1, N); throws std::invalid_argument otherwise.
std::pair<int, int> parseShard(const std::string& text) {
  int k = 0, n = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 1 || k > n ||
      n > 1 << 20)
    throw std::invalid_argument("--shard " + text + ": give K/N with 1 <= K <= N, e.g. 3/16");
  return {k - 1, n};
}

// Bakes one shard's tiles into the part file `out` (its journal, renamed into place when whole).
int runShard(const Options& o, const bounce::Scene& scene, bounce::BakeObserver& observer) {
  bounce::SceneBakeSettings settings = o.bake;
  settings.journal = o.out.string() + ".journal";
  try {
    bounce::bakeScene(scene, settings, &observer);
  } catch (const bounce::BakeCancelled&) {
    std::fprintf(stderr,
                 "\nbounce-bake: cancelled: %s holds the finished tiles; --resume goes on\n",
                 settings.journal.string().c_str());
    return 130;
  }
  std::filesystem::rename(settings.journal, o.out);
  std::fprintf(stderr, "bounce-bake: shard %s of %s -> %s (bounce-bake merge joins the parts)\n",
               o.shard.c_str(), o.scene.filename().string().c_str(), o.out.string().c_str());
  return 0;
}

int run(Options o) {
  // --threads bounds every stage, the load and the atlas too (their parallel loops run outside
  // the tiles' arenas).
  std::optional<tbb::global_control> threads;
  if (o.shared.threads > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism,
                    static_cast<std::size_t>(o.shared.threads));
  const auto start = std::chrono::steady_clock::now();
  const bounce::Scene scene = bounce::loadScene(o.scene);
  for (const std::string& warning : scene.warnings)
    std::fprintf(stderr, "bounce-bake: warning: %s\n", warning.c_str());
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.bake.maxDepth = o.shared.maxDepth;
  o.bake.seed = o.shared.seed;
  o.bake.threads = o.shared.threads;
  o.bake.backend = bounce::parseRayBackend(o.shared.backend);
  o.bake.lightChoice = *bounce::parseLightChoice(o.shared.lightChoice);  // checked by CLI11
  o.bake.denoise = o.denoise == "on";
  o.bake.gather = *bounce::parseGather(o.gather);  // checked by CLI11
  if (!o.maxMemory.empty()) o.bake.maxMemory = bounce::parseMemorySize(o.maxMemory);
  o.bake.resume = o.resume;
  bounce::listenForInterrupt();
  bounce::ProgressLineObserver observer(!o.quiet && (o.progress || bounce::stderrIsTerminal()));
  if (!o.shard.empty()) {
    std::tie(o.bake.shard, o.bake.shards) = parseShard(o.shard);
    if (o.out.empty())
      throw std::invalid_argument("--shard needs -o PART: the file its tiles go to");
    return runShard(o, scene, observer);
  }
  const std::filesystem::path out =
      o.out.empty() ? std::filesystem::path(o.scene).replace_extension(".bake") : o.out;
  // Finished tiles go to a journal beside the folder until the folder is written (--resume).
  o.bake.journal = out.string() + ".journal";
  if (o.mpi) {
#ifdef BOUNCE_HAVE_MPI
    return bounce::bakeOverMpi(scene, o.bake,
                               {out, o.scene, o.png, o.shared.exposure, loadSeconds, start},
                               !o.quiet && (o.progress || bounce::stderrIsTerminal()));
#else
    throw std::runtime_error(
        "--mpi: this bounce-bake was built without MPI (install libopenmpi-dev and rebuild); "
        "--shard K/N and 'bounce-bake merge' spread a bake without it");
#endif
  }
  if (!o.resume && std::filesystem::exists(o.bake.journal))
    std::fprintf(stderr,
                 "bounce-bake: note: starting afresh: %s held the tiles of an unfinished bake "
                 "(--resume would have gone on from them)\n",
                 o.bake.journal.string().c_str());
  bounce::SceneBake baked;
  try {
    baked = bounce::bakeScene(scene, o.bake, &observer);
  } catch (const bounce::BakeCancelled&) {
    std::fprintf(stderr,
                 "\nbounce-bake: cancelled: nothing written (%s is as it was); %s holds the "
                 "finished tiles: --resume goes on from them\n",
                 out.string().c_str(), o.bake.journal.string().c_str());
    return 130;
  }
  bounce::writeBakeAndReport(baked, {out, o.scene, o.png, o.shared.exposure, loadSeconds, start});
  std::filesystem::remove(o.bake.journal);
  return 0;
}

// How texels gather indirect light and when a dim one stops (docs/baker.md).
void addGatherOptions(CLI::App& app, Options& o) {
  app.add_option("--gather", o.gather,
                 "how texels gather indirect light: 'paths' (every sample a whole path) or "
                 "'cache' (a short bake of --cache-spp paths per texel first, then paths that "
                 "end at its map after one reflection; docs/baker.md)")
      ->check(CLI::IsMember({"paths", "cache"}));
  app.add_option("--cache-spp", o.bake.cacheSpp,
                 "samples per texel of the cache pass (--gather cache), half in each of its "
                 "two half caches (rounded up)")
      ->check(CLI::Range(1, 1 << 20));
  app.add_option("--error-floor", o.bake.errorFloor,
                 "with --gather cache: a texel dimmer than this fraction of the cache's mean "
                 "irradiance stops once its standard error is under --target-error times that "
                 "floor, an error the frame cannot show next to the scene's light; a probe the "
                 "same against this fraction of the delivered map's mean (0: every texel and "
                 "probe against its own mean; docs/baker.md)")
      ->check(CLI::Range(0.0, 100.0));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "merge") return bounce::bakeMergeMain(argc - 1, argv + 1);
  CLI::App app{
      "bounce-bake: bakes a scene's lightmap, irradiance E in W/m² per texel (by default the "
      "indirect light; lights marked extras.bounce.bake = \"all\" also their direct light), "
      "into a bake folder (lightmap.exr, layout.bin, bake.json). 'bounce-bake merge --help': "
      "joining "
      "the parts of a sharded bake."};
  Options o;
  app.option_defaults()->always_capture_default();
  bounce::SharedOptions& shared = o.shared;
  shared.maxDepth = kDefaults.maxDepth;
  shared.seed = kDefaults.seed;
  shared.threads = kDefaults.threads;
  shared.lightChoice = bounce::lightChoiceName(kDefaults.lightChoice);
  bounce::addSceneOption(app, shared);
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
  app.add_option("--spp", o.bake.maxSpp, "most samples per texel")->check(CLI::Range(16, 1 << 24));
  app.add_option("--target-error", o.bake.targetError,
                 "sample a texel until its relative standard error is below this (0: always "
                 "--spp)")
      ->check(CLI::Range(0.0, 1.0));
  bounce::addPathTracingOptions(app, shared);
  addGatherOptions(app, o);
  app.add_option("--denoise", o.denoise, "edge-aware denoiser (guided by normal, position, chart)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--png", o.png,
                 "also write a tone-mapped picture of the lightmap (E/pi, a white surface's "
                 "radiance) to look at");
  bounce::addExposureOption(app, shared);
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
  app.add_option("--tile-size", o.bake.tileSize,
                 "texels on a side of the tiles the irradiance and visibility are computed, "
                 "journalled and sharded in (the bake's bytes do not depend on it)")
      ->check(CLI::Range(1, 4096));
  app.add_flag("--resume", o.resume,
               "go on from the tiles in OUT.journal, left by a bake that was stopped or killed "
               "(its scene and settings must be this bake's); the result is the same bytes as "
               "an uninterrupted bake");
  app.add_option("--shard", o.shard,
                 "K/N: bake only the K-th of N shares of the tiles into the part file -o PART; "
                 "'bounce-bake merge PART_1 ... PART_N -o DIR' then writes the bake folder, the "
                 "same bytes as one process's bake");
  app.add_flag("--mpi", o.mpi,
               "one bake over every rank of 'mpirun -np N bounce-bake SCENE -o DIR --mpi': rank 0 "
               "hands out tiles, costliest first, gathers them and writes the folder (the same "
               "bytes as one process); every rank reads SCENE");
  app.add_flag("--progress", o.progress, "draw the progress line even when stderr is no terminal");
  app.add_flag("--quiet", o.quiet, "no progress line (the summary line is still printed)");
  CLI11_PARSE(app, argc, argv);
  o.scene = shared.scene;
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-bake: error: %s\n", e.what());
    return 1;
  }
}
