// The bake in tiles (bake/tile_grid.h, pipeline/tile_journal.h): a texel's bytes never depend on
// the tiles, the thread count, a kill and a resume, or the shard that baked it. Each test compares
// whole bake folders byte for byte (bake.json but for its run-dependent measurements), against a
// bake of the same settings made in one go.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake_folder/probe_file.h"
#include "io/load_error.h"
#include "pipeline/scene_bake.h"
#include "pipeline/tile_journal.h"
#include "scene/load.h"
#include "support/tool_run.h"

extern char** environ;

namespace bounce {
namespace {

namespace fs = std::filesystem;

const fs::path kCornell = fs::path(BOUNCE_SOURCE_DIR) / "content/cornell_box/cornell_box.gltf";
const std::string kBakeTool = std::string(BOUNCE_BIN_DIR) + "/bounce-bake";
// Small tiles on a small atlas: about a hundred tiles, so kills land between and inside them.
const std::vector<std::string> kSettings = {"--texel-budget", "8192", "--spp",       "128",
                                            "--cache-spp",    "8",    "--tile-size", "8",
                                            "--vpls",         "512"};

// bake.json without what a run measures ("measured": times, memory, rates): what must be the
// same.
nlohmann::json withoutMeasurements(nlohmann::json m) {
  m.erase("measured");
  return m;
}

// Every file of `a` in `b` with the same bytes, bake.json the same but for its measurements.
void expectSameBake(const fs::path& a, const fs::path& b, const std::string& context) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    const fs::path name = entry.path().filename();
    ++files;
    ASSERT_TRUE(fs::exists(b / name)) << context << ": " << b / name << " is missing";
    if (name == "bake.json")
      EXPECT_EQ(withoutMeasurements(nlohmann::json::parse(test::readText(a / name))),
                withoutMeasurements(nlohmann::json::parse(test::readText(b / name))))
          << context;
    else
      EXPECT_TRUE(test::readText(a / name) == test::readText(b / name))
          << context << ": " << name << " differs";
  }
  EXPECT_GE(files, 5) << context;  // layout, lightmap, error map, visibility, VPLs, bake.json
  int inB = 0;
  for (const auto& entry : fs::directory_iterator(b)) inB += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(inB, files) << context;
}

std::string bakeCommand(const fs::path& out, const std::string& extra) {
  std::string command =
      kBakeTool + " " + test::shellQuote(kCornell) + " -o " + test::shellQuote(out);
  for (const std::string& s : kSettings) command += " " + s;
  return command + " --quiet " + extra;
}

// Starts bounce-bake with `args` (after the tool), its output to `log`; returns its pid.
pid_t startBake(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all = {kBakeTool};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, kBakeTool.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return failed ? -1 : pid;
}

std::string partName(int k) {
  std::string name = "part";
  name += std::to_string(k);
  return name;
}

class TileBake : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = "bounce_tiles_";
    name += ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  // The bake made in one go, and how long it took.
  double bakeWhole(const fs::path& out) {
    const auto start = std::chrono::steady_clock::now();
    const test::ToolRun r = test::runCommand(bakeCommand(out, ""), dir_ / "whole.log");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_FALSE(fs::exists(out.string() + ".journal")) << "the journal outlived its bake";
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  fs::path dir_;
};

// kill -9 at random moments, five times, each run resuming the last: the first anywhere in the
// first 30% of an uninterrupted bake's time, the others a random 0-25% of it after the run's
// first new tile (so they land among the tiles, in the stages after them or in the writing),
// then one run to the end. The folder must be the uninterrupted bake's bytes, and at least two
// kills must have landed with tiles journalled but the bake unfinished (else it proved nothing).
TEST_F(TileBake, ResumeAfterKillsAtRandomMomentsGivesTheSameBytes) {
  const double seconds = bakeWhole(dir_ / "whole.bake");
  const fs::path out = dir_ / "resumed.bake";
  const fs::path journal = out.string() + ".journal";
  std::vector<std::string> args = {kCornell.string(), "-o", out.string()};
  args.insert(args.end(), kSettings.begin(), kSettings.end());
  args.push_back("--quiet");
  args.push_back("--resume");
  std::random_device device;
  const unsigned seed = device();
  std::mt19937 random(seed);
  std::string kills;
  int midBake = 0;
  for (int k = 0; k < 5 && !fs::exists(out); ++k) {
    std::error_code ec;
    const uintmax_t before = fs::exists(journal) ? fs::file_size(journal, ec) : 0;
    const pid_t pid = startBake(args, dir_ / "kills.log");
    ASSERT_GT(pid, 0);
    int status = 0;
    if (k > 0)  // wait for the first new tile (or the end)
      for (int i = 0; i < 20000 && ::waitpid(pid, &status, WNOHANG) == 0; ++i) {
        if (fs::exists(journal) && fs::file_size(journal, ec) > before + 4096) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    const double after =
        std::uniform_real_distribution<double>(0.0, k == 0 ? 0.3 : 0.25)(random) * seconds;
    std::this_thread::sleep_for(std::chrono::duration<double>(after));
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    const bool killed = WIFSIGNALED(status);
    const std::size_t records = fs::exists(journal) ? readTileJournal(journal).records.size() : 0;
    kills += ' ';
    kills += std::to_string(after);
    kills += killed ? " s (killed, " : " s (had finished, ";
    kills += std::to_string(records);
    kills += " tiles journalled)";
    if (killed && records > 0 && !fs::exists(out)) ++midBake;
  }
  const test::ToolRun last = test::runCommand(bakeCommand(out, "--resume"), dir_ / "last.log");
  ASSERT_EQ(last.exitCode, 0) << last.output;
  const std::string context = "random seed " + std::to_string(seed) + ", kills after" + kills;
  std::printf("%s; whole bake %.3f s\n", context.c_str(), seconds);
  EXPECT_GE(midBake, 2) << context;
  EXPECT_FALSE(fs::exists(journal)) << context;
  for (const auto& entry : fs::directory_iterator(dir_))  // a kill while writing leaves one
    EXPECT_EQ(entry.path().filename().string().find("resumed.bake.tmp-"), std::string::npos)
        << context << ": " << entry.path() << " was left";
  expectSameBake(dir_ / "whole.bake", out, context);
}

// Three shards, merged from parts given in another order: the one-process bake's bytes. A merge
// missing a part, or with a part of other settings, is refused with what is wrong.
TEST_F(TileBake, ShardsMergeToTheBytesOfOneProcess) {
  bakeWhole(dir_ / "whole.bake");
  for (int k = 1; k <= 3; ++k) {
    const test::ToolRun r = test::runCommand(
        bakeCommand(dir_ / partName(k), "--shard " + std::to_string(k) + "/3"), dir_ / "shard.log");
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  const auto merge = [&](const std::string& parts, const fs::path& out) {
    return test::runCommand(
        kBakeTool + " merge " + parts + " -o " + test::shellQuote(out) + " --quiet",
        dir_ / "merge.log");
  };
  const auto part = [&](int k) { return test::shellQuote(dir_ / partName(k)) + " "; };
  const test::ToolRun merged = merge(part(3) + part(1) + part(2), dir_ / "merged.bake");
  ASSERT_EQ(merged.exitCode, 0) << merged.output;
  expectSameBake(dir_ / "whole.bake", dir_ / "merged.bake", "merged from 3 shards");

  const test::ToolRun missing = merge(part(1) + part(3), dir_ / "missing.bake");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("shards 2 of 3 are missing"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(dir_ / "missing.bake"));

  const test::ToolRun other =
      test::runCommand(bakeCommand(dir_ / "other2", "--shard 2/3 --seed 7"), dir_ / "shard.log");
  ASSERT_EQ(other.exitCode, 0) << other.output;
  const test::ToolRun mixed =
      merge(part(1) + test::shellQuote(dir_ / "other2") + " " + part(3), dir_ / "mixed.bake");
  EXPECT_EQ(mixed.exitCode, 1);
  EXPECT_NE(mixed.output.find("its seed is 7, this bake's is 0"), std::string::npos)
      << mixed.output;
  EXPECT_FALSE(fs::exists(dir_ / "mixed.bake"));
}

#ifdef BOUNCE_MPIEXEC
// mpirun -np 2 (oversubscribed, as root with OpenMPI's two variables): rank 0 and rank 1 both
// compute tiles, and the folder is the one-process bake's bytes. Leak checks are off for it
// (under the sanitizer preset): OpenMPI does not free what it allocates at start.
TEST_F(TileBake, MpiRanksBakeTheBytesOfOneProcess) {
  bakeWhole(dir_ / "whole.bake");
  const test::ToolRun r = test::runCommand(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
      "OMPI_MCA_rmaps_base_oversubscribe=1 "
      "LSAN_OPTIONS=detect_leaks=0 " BOUNCE_MPIEXEC " --bind-to none -np 2 " +
          bakeCommand(dir_ / "mpi.bake", "--mpi"),
      dir_ / "mpi.log");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int rank0 = 0, rank1 = 0;
  const std::size_t at = r.output.find("tiles computed by rank 0, 1, ...: ");
  ASSERT_NE(at, std::string::npos) << r.output;
  ASSERT_EQ(std::sscanf(r.output.c_str() + at, "tiles computed by rank 0, 1, ...: %d, %d", &rank0,
                        &rank1),
            2)
      << r.output;
  EXPECT_GT(rank0, 0) << r.output;
  EXPECT_GT(rank1, 0) << r.output;
  expectSameBake(dir_ / "whole.bake", dir_ / "mpi.bake", "mpirun -np 2");
}
#endif

// The probe stage the same way: the Cornell box's short block sent to the probes
// (lightmapScale 0), baked on one thread with 7-texel tiles and on all cores with 64-texel tiles,
// gives the same probes.bin bytes (each probe a function of the scene, the settings and its index).
TEST(Tiles, TheProbesDoNotDependOnTheTileSizeOrTheThreads) {
  Scene scene = loadScene(kCornell);
  bool found = false;
  for (Instance& instance : scene.instances)
    if (instance.name == "short_block") {
      instance.lightmapScale = 0.0f;
      found = true;
    }
  ASSERT_TRUE(found);
  SceneBakeSettings a;
  a.texelBudget = 1024;
  a.maxSpp = 256;
  a.vpls = 0;
  a.tileSize = 7;
  a.threads = 1;
  SceneBakeSettings b = a;
  b.tileSize = 64;
  b.threads = 0;
  const SceneBake x = bakeScene(scene, a), y = bakeScene(scene, b);
  ASSERT_TRUE(x.folder.probes && y.folder.probes);
  EXPECT_GE(x.folder.probes->grids.size(), 1u);  // the block, and what the coarse atlas adds
  // With the probe-lit instances' visibility per triangle corner (12 triangles of the block).
  EXPECT_GE(x.folder.probes->visibility.corners.size(), 36u);
  EXPECT_EQ(encodeProbes(*x.folder.probes), encodeProbes(*y.folder.probes));
  ASSERT_TRUE(x.folder.manifest.probes && y.folder.manifest.probes);
  EXPECT_EQ(x.folder.manifest.probes->samplesTotal, y.folder.manifest.probes->samplesTotal);
}

// In the library: 7-texel tiles on one thread and 64-texel tiles on all cores give the same
// lightmap, error map and visibility bit for bit.
TEST(Tiles, TheBakeDoesNotDependOnTheTileSizeOrTheThreads) {
  const Scene scene = loadScene(kCornell);
  SceneBakeSettings a;
  a.texelBudget = 2048;
  a.maxSpp = 32;
  a.vpls = 0;
  a.tileSize = 7;
  a.threads = 1;
  SceneBakeSettings b = a;
  b.tileSize = 64;
  b.threads = 0;
  const SceneBake x = bakeScene(scene, a), y = bakeScene(scene, b);
  EXPECT_TRUE(x.folder.irradiance.pixels == y.folder.irradiance.pixels);
  EXPECT_TRUE(x.folder.relativeError->pixels == y.folder.relativeError->pixels);
  ASSERT_TRUE(x.folder.visibility && y.folder.visibility);
  for (std::size_t t = 0; t < x.folder.visibility->texels.size(); ++t) {
    ASSERT_EQ(x.folder.visibility->texels[t].light, y.folder.visibility->texels[t].light) << t;
    ASSERT_EQ(x.folder.visibility->texels[t].visible, y.folder.visibility->texels[t].visible) << t;
  }
  EXPECT_GT(x.tiles, 20u);
  BakeManifest mx = x.folder.manifest, my = y.folder.manifest;
  mx.measured = my.measured = {};
  EXPECT_EQ(manifestText(mx), manifestText(my));
}

// A journal cut inside its last record (a kill in the middle of a write) keeps the whole records
// before it; a damaged record ends the journal there; a journal of another bake is refused with
// the field that differs.
TEST(TileJournalFile, KeepsTheWholeRecordsAndRefusesAnotherBakesJournal) {
  const fs::path file = fs::temp_directory_path() / "bounce_tile_journal_test.journal";
  const nlohmann::json key = {{"seed", 0}, {"spp", 64}, {"scene", "/a/box.gltf"}};
  {
    TileJournalWriter writer(file, key);
    for (uint32_t t = 0; t < 3; ++t)
      writer.append({TileStage::Irradiance, t, std::vector<unsigned char>(100 + t, 7), {}});
  }
  const TileJournal whole = readTileJournal(file);
  ASSERT_EQ(whole.records.size(), 3u);
  EXPECT_EQ(whole.records[2].bytes.size(), 102u);
  EXPECT_EQ(whole.droppedBytes, 0u);
  EXPECT_EQ(whole.key, key);

  fs::resize_file(file, fs::file_size(file) - 5);
  const TileJournal cut = readTileJournal(file);
  EXPECT_EQ(cut.records.size(), 2u);
  EXPECT_GT(cut.droppedBytes, 100u);
  {  // goes on after the whole records
    TileJournalWriter writer(file, cut);
    writer.append({TileStage::Visibility, 9, std::vector<unsigned char>(10, 1), {}});
  }
  const TileJournal resumed = readTileJournal(file);
  ASSERT_EQ(resumed.records.size(), 3u);
  EXPECT_EQ(resumed.records[2].tile, 9u);
  EXPECT_EQ(resumed.records[2].stage, TileStage::Visibility);

  std::string bytes = test::readText(file);
  bytes[bytes.size() - 12] ^= 0x10;  // inside the last record's payload (10 bytes, then the check)
  { std::ofstream(file, std::ios::binary) << bytes; }
  EXPECT_EQ(readTileJournal(file).records.size(), 2u);

  nlohmann::json other = key;
  other["seed"] = 7;
  other["scene"] = "/b/box.gltf";
  try {
    constexpr const char* kSceneOnly[] = {"scene"};
    checkTileJournalKey(file, key, other, kSceneOnly);
    ADD_FAILURE() << "another bake's journal was taken";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("its seed is 0, this bake's is 7"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(checkTileJournalKey(file, key, nlohmann::json(key), {}));
  fs::remove(file);
}

// A bake's journal cut to its first half of tiles (what a kill leaves: whole records in the
// order they finished), the scene file then edited in place (the green wall's albedo: the same
// path, the same atlas, another scene hash), resumed: the journal's tiles are of the old scene,
// so the resume must refuse the journal, naming it and the scene hash, or start over and give a
// fresh bake's bytes; it must never restore them beside tiles of the new scene.
// Injected: the journal key without "sceneHash": the resume restored the old tiles and the
// lightmap differed from a fresh bake's.
TEST(TileJournalFile, AResumeAfterTheSceneFileChangedNeverMixesTheTwoScenes) {
  const fs::path dir = fs::temp_directory_path() / "bounce_tiles_scene_changed";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path sceneFile = dir / "box.gltf";
  fs::copy_file(kCornell, sceneFile);
  SceneBakeSettings settings;
  settings.texelBudget = 1024;
  settings.maxSpp = 32;
  settings.vpls = 0;
  settings.tileSize = 8;
  settings.threads = 1;
  settings.journal = dir / "box.bake.journal";
  bakeScene(loadScene(sceneFile), settings, nullptr);  // the library leaves its journal
  {
    const TileJournal whole = readTileJournal(settings.journal);
    ASSERT_GE(whole.records.size(), 8u);
    TileJournalWriter cut(settings.journal, whole.key);
    for (std::size_t r = 0; r < whole.records.size() / 2; ++r) cut.append(whole.records[r]);
  }

  nlohmann::json gltf = nlohmann::json::parse(test::readText(sceneFile));
  for (nlohmann::json& material : gltf["materials"])
    if (material["name"] == "green")
      material["pbrMetallicRoughness"]["baseColorFactor"] = {0.45, 0.14, 0.091, 1.0};
  std::ofstream(sceneFile, std::ios::trunc) << gltf.dump();
  const Scene changed = loadScene(sceneFile);

  SceneBakeSettings fresh = settings;
  fresh.journal.clear();
  const SceneBake expected = bakeScene(changed, fresh, nullptr);
  settings.resume = true;
  try {
    const SceneBake resumed = bakeScene(changed, settings, nullptr);
    EXPECT_EQ(resumed.tilesRestored, 0) << "restored tiles of the scene before its change";
    EXPECT_TRUE(resumed.folder.irradiance.pixels == expected.folder.irradiance.pixels)
        << "the lightmap mixes tiles of the two scenes";
  } catch (const LoadError& e) {
    const std::string why = e.what();
    EXPECT_NE(why.find(settings.journal.string()), std::string::npos) << why;
    EXPECT_NE(why.find("sceneHash"), std::string::npos) << why;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace bounce
