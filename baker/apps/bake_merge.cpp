#include "bake_merge.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bake_progress_line.h"
#include "bake_summary.h"
#include "io/load_error.h"
#include "pipeline/scene_bake.h"
#include "pipeline/tile_journal.h"
#include "scene/load.h"
#include "trace/progress_line.h"

namespace bounce {
namespace {

struct MergeOptions {
  std::vector<std::filesystem::path> parts;
  std::filesystem::path out;
  std::filesystem::path scene;  // empty: the one the parts name
  int threads = 0;
  bool progress = false, quiet = false;
};

// "K/N" of a part's key, into (K, N); throws LoadError naming the part otherwise.
std::pair<int, int> shardOf(const std::filesystem::path& part, const nlohmann::json& key) {
  int k = 0, n = 0;
  const auto it = key.find("shard");
  if (it == key.end() || !it->is_string() ||
      std::sscanf(it->get<std::string>().c_str(), "%d/%d", &k, &n) != 2 || k < 1 || k > n)
    throw LoadError(part, "names no shard K/N: not a part of a sharded bake");
  return {k, n};
}

int merge(const MergeOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  // Every part of one bake, each shard once.
  const nlohmann::json first = readTileJournalKey(o.parts.front());
  const int shards = shardOf(o.parts.front(), first).second;
  std::map<int, std::filesystem::path> byShard;
  for (const std::filesystem::path& part : o.parts) {
    const nlohmann::json key = readTileJournalKey(part);
    checkTileJournalKey(part, key, first, kTileKeyNotShared);
    const auto [k, n] = shardOf(part, key);
    if (n != shards)
      throw LoadError(part, "is shard " + std::to_string(k) + "/" + std::to_string(n) + ", " +
                                o.parts.front().string() + " is one of " + std::to_string(shards));
    if (!byShard.emplace(k, part).second)
      throw LoadError(part, "is shard " + std::to_string(k) + "/" + std::to_string(n) + ", as is " +
                                byShard[k].string());
  }
  std::string missing;
  for (int k = 1; k <= shards; ++k)
    if (!byShard.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty())
    throw std::runtime_error("shards " + missing + " of " + std::to_string(shards) +
                             " are missing: give every part of the bake");

  const std::filesystem::path sceneFile =
      o.scene.empty() ? std::filesystem::path(first.at("scene").get<std::string>()) : o.scene;
  const Scene scene = loadScene(sceneFile);
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SceneBakeSettings settings = bakeSettingsFromInputs(o.parts.front(), first);
  settings.threads = o.threads;
  settings.parts = o.parts;
  listenForInterrupt();
  ProgressLineObserver observer(!o.quiet && (o.progress || stderrIsTerminal()));
  SceneBake baked;
  try {
    baked = bakeScene(scene, settings, &observer);
  } catch (const BakeCancelled&) {
    std::fprintf(stderr, "\nbounce-bake: merge cancelled: nothing written (%s is as it was)\n",
                 o.out.string().c_str());
    return 130;
  }
  writeBakeAndReport(baked, {o.out, sceneFile, {}, 0.0f, loadSeconds, start});
  return 0;
}

}  // namespace

int bakeMergeMain(int argc, char** argv) {
  CLI::App app{
      "bounce-bake merge: writes the bake folder from the parts of a sharded bake (bounce-bake "
      "SCENE -o PART_K --shard K/N, one per K): it runs the stages that need the whole map "
      "(dilation, seams, denoiser, VPLs, probes). The folder is the same, byte for byte, as one "
      "process's bake with the same settings."};
  MergeOptions o;
  app.add_option("parts", o.parts, "the part files, every shard once")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("-o,--out", o.out, "bake folder to write")->required();
  app.add_option("--scene", o.scene,
                 "the scene (default: the path the parts were baked from; its content must hash "
                 "the same)");
  app.add_option("--threads", o.threads, "worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024));
  app.add_flag("--progress", o.progress, "draw the progress line even when stderr is no terminal");
  app.add_flag("--quiet", o.quiet, "no progress line (the summary line is still printed)");
  app.name("bounce-bake merge");
  CLI11_PARSE(app, argc, argv);
  try {
    return merge(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-bake: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace bounce
