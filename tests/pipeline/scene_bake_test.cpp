// The scene bake as a library call (pipeline/scene_bake.h): its stages reach the observer in
// order, numbered from the plan, each finished with all its work done; an observer that says
// stop in any stage ends the bake there with BakeCancelled and no later stage; bounce-bake
// writes exactly what bakeScene returns; and an interrupted bounce-bake writes nothing and
// leaves the previous bake folder as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bake/texel_coverage.h"
#include "bake_folder/bake_folder.h"
#include "image/image_io.h"
#include "pipeline/scene_bake.h"
#include "scene/load.h"
#include "support/tool_run.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

const fs::path kCornell = fs::path(BOUNCE_SOURCE_DIR) / "content/cornell_box/cornell_box.gltf";

SceneBakeSettings smallBake() {
  SceneBakeSettings s;
  s.texelBudget = 1024;
  s.maxSpp = 32;
  s.vpls = 256;
  return s;
}

// Records every report; says stop at the first report of stage `stopAt` (0: never).
struct RecordingObserver final : BakeObserver {
  int stopAt = 0;
  std::vector<BakeProgress> seen;
  bool onProgress(const BakeProgress& p) override {
    seen.push_back(p);
    return p.stage != stopAt;
  }
};

TEST(SceneBake, StagesReachTheObserverInOrderEachFinished) {
  const Scene scene = loadScene(kCornell);
  const SceneBakeSettings settings = smallBake();
  const std::vector<std::string> plan = sceneBakeStages(scene, settings);
  ASSERT_EQ(plan.size(), 9u);  // the box's light is a static area light: visibility runs
  RecordingObserver observer;
  const SceneBake baked = bakeScene(scene, settings, &observer);
  int stage = 0;
  uint64_t done = 0;
  std::vector<int> finished(plan.size() + 1, 0);
  for (const BakeProgress& p : observer.seen) {
    EXPECT_EQ(p.stages, static_cast<int>(plan.size()));
    ASSERT_GE(p.stage, stage) << "stage " << p.stage << " after " << stage;
    if (p.stage != stage) done = 0;
    stage = p.stage;
    EXPECT_EQ(p.name, plan[static_cast<std::size_t>(p.stage - 1)]);
    EXPECT_GE(p.done, done) << p.name;
    EXPECT_LE(p.done, p.total) << p.name;
    done = p.done;
    if (p.finished) {
      EXPECT_EQ(p.done, p.total) << p.name;
      ++finished[static_cast<std::size_t>(p.stage)];
    }
  }
  for (std::size_t k = 1; k <= plan.size(); ++k) EXPECT_EQ(finished[k], 1) << plan[k - 1];
  EXPECT_TRUE(baked.folder.vpls.has_value());
  EXPECT_TRUE(baked.folder.visibility.has_value());
  // bake.json round-trips through its text whole (with a file record, as writeBake adds).
  BakeManifest m = baked.folder.manifest;
  m.files["layout.bin"] = {.bytes = 152, .hash = "0123456789abcdef"};
  EXPECT_EQ(manifestText(parseManifest("bake.json", manifestText(m))), manifestText(m));
}

TEST(SceneBake, AnObserverCancelsInEveryStage) {
  const Scene scene = loadScene(kCornell);
  const SceneBakeSettings settings = smallBake();
  const int stages = static_cast<int>(sceneBakeStages(scene, settings).size());
  for (int stopAt = 1; stopAt <= stages; ++stopAt) {
    RecordingObserver observer;
    observer.stopAt = stopAt;
    EXPECT_THROW(bakeScene(scene, settings, &observer), BakeCancelled) << "stage " << stopAt;
    for (const BakeProgress& p : observer.seen) {
      EXPECT_LE(p.stage, stopAt) << "stage " << p.stage << " ran after a cancel in " << stopAt;
      EXPECT_FALSE(p.stage == stopAt && p.finished) << "stage " << stopAt << " finished";
    }
  }
}

// Stopped in the middle of a long irradiance stage (the first report with rows done), the bake
// ends there: the stage never finishes and no later stage starts.
TEST(SceneBake, ACancelInTheMiddleOfAStageEndsIt) {
  const Scene scene = loadScene(kCornell);
  SceneBakeSettings settings = smallBake();
  settings.maxSpp = 4096;
  settings.targetError = 0.0f;  // every texel takes all its samples: seconds of work
  settings.threads = 1;
  struct MidStage final : BakeObserver {
    std::vector<BakeProgress> seen;
    bool onProgress(const BakeProgress& p) override {
      seen.push_back(p);
      return !(p.name == "irradiance" && p.done > 0 && !p.finished);
    }
  } observer;
  EXPECT_THROW(bakeScene(scene, settings, &observer), BakeCancelled);
  ASSERT_FALSE(observer.seen.empty());
  const BakeProgress& last = observer.seen.back();
  EXPECT_EQ(last.name, "irradiance");
  EXPECT_FALSE(last.finished);
  EXPECT_LT(last.done, last.total);
}

TEST(SceneBake, BounceBakeWritesWhatBakeSceneReturns) {
  const Scene scene = loadScene(kCornell);
  const SceneBake baked = bakeScene(scene, smallBake());
  const fs::path out = fs::temp_directory_path() / "bounce_scene_bake_test.bake";
  fs::remove_all(out);
  const test::ToolRun r = test::runCommand(
      std::string(BOUNCE_BIN_DIR) + "/bounce-bake " + test::shellQuote(kCornell) + " -o " +
          test::shellQuote(out) + " --texel-budget 1024 --spp 32 --vpls 256 --quiet",
      fs::temp_directory_path() / "bounce_scene_bake_test.log");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Bake written = readBake(out, scene);
  EXPECT_TRUE(written.irradiance.pixels == baked.folder.irradiance.pixels);
  EXPECT_TRUE(written.relativeError->pixels == baked.folder.relativeError->pixels);
  EXPECT_EQ(written.vpls->size(), baked.folder.vpls->size());
  fs::remove_all(out);
}

// --max-memory: a budget under the estimate refuses the bake after the atlas, before anything
// large is allocated, with the estimate and what lowers it, and writes nothing; a bake under
// its budget records the estimate and the measured peak, and on the Cornell box (a fresh
// process) they agree within 20% (over four scenes the estimate was within -6% and +4% of the
// measured peak, docs/baker.md "Memory"; counting the sample points once while their list grew
// by doubling made it 26% low here, which failed).
TEST(SceneBake, MemoryBudgetRefusesABakeOverItAndTheEstimateHolds) {
  const fs::path dir = fs::temp_directory_path() / "bounce_scene_bake_memory";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string bake = std::string(BOUNCE_BIN_DIR) + "/bounce-bake " +
                           test::shellQuote(kCornell) + " -o " + test::shellQuote(dir / "b.bake");
  const test::ToolRun refused = test::runCommand(bake + " --max-memory 5M --quiet", dir / "a.log");
  EXPECT_EQ(refused.exitCode, 1) << refused.output;
  EXPECT_NE(refused.output.find("the bake would take about"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("over the budget of 5 MB"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(dir / "b.bake"));
#ifdef __SANITIZE_ADDRESS__
  fs::remove_all(dir);
  GTEST_SKIP() << "the refusal holds; the estimate is a release build's (AddressSanitizer's "
                  "shadow memory, red zones and quarantine are not in it)";
#endif
  const test::ToolRun baked =
      test::runCommand(bake + " --max-memory 2G --spp 16 --quiet", dir / "b.log");
  ASSERT_EQ(baked.exitCode, 0) << baked.output;
  const BakeManifest manifest =
      parseManifest("bake.json", test::readText(dir / "b.bake" / "bake.json"));
  const double estimated = manifest.measured.estimatedPeakBytes;
  const double measured = manifest.measured.peakBytes;
  EXPECT_GT(measured, 0.0);
  EXPECT_NEAR(estimated, measured, 0.2 * measured);
  fs::remove_all(dir);
}

// The same estimate where the covered texels carry it: the Cornell box at 2^17 texels (742 × 192,
// 93% covered, 2.7 mm texels; 16 spp, no VPLs, about 10 s). There the per-covered-texel terms
// (150 B of arrays and 8 × 48 B of sample points) are about 60% of the estimate, where the default
// bake above (20k texels) has the process's own resident set dominate it. Estimate and measured
// peak agree within 10% (measured: 114.0 MB against 118.6 MB, -3.8%; four scenes -6%..+4%,
// docs/baker.md "Memory"). Injected: 15 B per covered texel instead of 150 (ten times too small):
// the estimate 96 MB, -19%, fails here and passes the test above.
TEST(SceneBake, MemoryEstimateHoldsWhereCoveredTexelsCarryIt) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP()
      << "the estimate is a release build's (AddressSanitizer's shadow memory is not in it)";
#endif
  const fs::path dir = fs::temp_directory_path() / "bounce_scene_bake_memory_texels";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const test::ToolRun baked = test::runCommand(
      std::string(BOUNCE_BIN_DIR) + "/bounce-bake " + test::shellQuote(kCornell) + " -o " +
          test::shellQuote(dir / "b.bake") + " --texel-budget 131072 --spp 16 --vpls 0 --quiet",
      dir / "b.log");
  ASSERT_EQ(baked.exitCode, 0) << baked.output;
  const BakeManifest manifest =
      parseManifest("bake.json", test::readText(dir / "b.bake" / "bake.json"));
  const double texels = static_cast<double>(manifest.atlas.width) * manifest.atlas.height;
  ASSERT_GT(texels, 120000.0);
  ASSERT_GT(static_cast<double>(manifest.atlas.coveredTexels), 0.85 * texels);
  const double estimated = manifest.measured.estimatedPeakBytes;
  const double measured = manifest.measured.peakBytes;
  // The covered texels' sample points alone (8 a texel, texel_coverage.h) are over 40% of the
  // measured peak, or the test would prove nothing about the covered texels' terms.
  ASSERT_GT(static_cast<double>(manifest.atlas.coveredTexels) * 8.0 * sizeof(TexelPoint),
            0.4 * measured);
  EXPECT_NEAR(estimated, measured, 0.1 * measured);
  fs::remove_all(dir);
}

// SIGINT in the irradiance stage: exit 130, "cancelled: nothing written", the bake folder
// written before byte for byte as it was, no temporary folder beside it.
TEST(SceneBake, InterruptedBounceBakeLeavesThePreviousFolder) {
  const fs::path dir = fs::temp_directory_path() / "bounce_scene_bake_interrupt";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path out = dir / "box.bake";
  const std::string bake = std::string(BOUNCE_BIN_DIR) + "/bounce-bake " +
                           test::shellQuote(kCornell) + " -o " + test::shellQuote(out);
  ASSERT_EQ(test::runCommand(bake + " --texel-budget 256 --spp 16 --vpls 0 --quiet", dir / "a.log")
                .exitCode,
            0);
  const std::string before = test::readText(out / "lightmap.exr");
  ASSERT_FALSE(before.empty());
  // A long bake (4096 spp, no early stop), interrupted once its irradiance stage has begun.
  const fs::path log = dir / "b.log";
  const test::ToolRun r = test::runCommand(
      "(" + bake + " --spp 4096 --target-error 0 --threads 1 --progress 2> " +
          test::shellQuote(log) + " & pid=$!; for i in $(seq 1 600); do grep -q irradiance " +
          test::shellQuote(log) + " && break; sleep 0.05; done; kill -INT $pid; wait $pid; " +
          "echo exit=$?; cat " + test::shellQuote(log) + ")",
      dir / "c.log");
  EXPECT_NE(r.output.find("exit=130"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cancelled: nothing written"), std::string::npos) << r.output;
  EXPECT_EQ(test::readText(out / "lightmap.exr"), before);
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.is_directory() ? 1 : 0;
  EXPECT_EQ(entries, 1) << "a temporary folder was left beside the bake";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace bounce
