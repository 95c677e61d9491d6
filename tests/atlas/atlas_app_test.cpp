// bounce-atlas end to end: the report, the picture and the exit codes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include "image/image_compare.h"
#include "support/tool_run.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

const std::string kTool = std::string(BOUNCE_BIN_DIR) + "/bounce-atlas";
const fs::path kCornell = fs::path(BOUNCE_SOURCE_DIR) / "content/cornell_box/cornell_box.gltf";

fs::path scratchDir() {
  return fs::temp_directory_path() / ("bounce_atlas_app_test_" + std::to_string(::getpid()));
}

using test::readText;

// Runs the tool with its output to `out`; returns the exit code.
int run(const std::string& arguments, const fs::path& out) {
  return test::runCommand(kTool + " " + arguments, out).exitCode;
}

TEST(AtlasApp, ReportsTheCornellAtlasAndDrawsIt) {
  fs::create_directories(scratchDir());
  const fs::path out = scratchDir() / "report.json", png = scratchDir() / "atlas.png";
  ASSERT_EQ(run(kCornell.string() + " --json --png " + png.string() + " --png-scale 1", out), 0)
      << readText(out);
  const nlohmann::json report = nlohmann::json::parse(readText(out));
  EXPECT_EQ(report["charts"].get<int>(), 16);  // 6 flat walls and light, 2 × 5 block faces
  EXPECT_EQ(report["chartKinds"]["planar"].get<int>(), 16);
  EXPECT_GE(report["utilisation"].get<double>(), 0.6);
  const Mask picture = readMask(png);  // any PNG reader: the size is what is checked here
  EXPECT_EQ(picture.width, report["width"].get<int>());
  EXPECT_EQ(picture.height, report["height"].get<int>());
  fs::remove_all(scratchDir());
}

// The preview is the bake's atlas: bounce-atlas and bounce-bake share the texel rule and every
// default, so with no options both report the same texel size, atlas size and chart count; a
// cap below the rule's texels coarsens both alike and says so.
TEST(AtlasApp, AgreesWithTheBakeAndNamesTheCap) {
  fs::create_directories(scratchDir());
  for (const std::string options : {"", " --max-texels 2000"}) {
    const fs::path report = scratchDir() / "report.json", bake = scratchDir() / "cornell.bake";
    const test::ToolRun atlasRun =
        test::runCommand(kTool + " " + kCornell.string() + " --json" + options, report);
    ASSERT_EQ(atlasRun.exitCode, 0) << readText(report);
    const nlohmann::json atlas = nlohmann::json::parse(readText(report));
    const fs::path log = scratchDir() / "bake.txt";
    ASSERT_EQ(test::runCommand(std::string(BOUNCE_BIN_DIR) + "/bounce-bake " + kCornell.string() +
                                   " -o " + bake.string() + " --spp 16 --vpls 0" + options,
                               log)
                  .exitCode,
              0)
        << readText(log);
    const nlohmann::json manifest = nlohmann::json::parse(readText(bake / "bake.json"));
    const nlohmann::json& baked = manifest.at("atlas");
    EXPECT_EQ(baked.at("texelSize").get<double>(), atlas.at("texelSizeMetres").get<double>());
    EXPECT_EQ(baked.at("width").get<int>(), atlas.at("width").get<int>());
    EXPECT_EQ(baked.at("height").get<int>(), atlas.at("height").get<int>());
    EXPECT_EQ(baked.at("charts").get<int>(), atlas.at("charts").get<int>());
    EXPECT_EQ(baked.at("texelRule"), atlas.at("texelRule"));
    const double area = atlas.at("weightedAreaSquareMetres").get<double>();
    const double t = atlas.at("texelSizeMetres").get<double>();
    if (options.empty()) {
      EXPECT_NEAR(t, std::sqrt(area / 16384.0), 1e-6 * t);  // a small scene's 16384 texels
    } else {
      EXPECT_NEAR(t, std::sqrt(area / 2000.0), 1e-6 * t);
      EXPECT_NE(readText(log).find("over the cap of 2000"), std::string::npos) << readText(log);
      EXPECT_EQ(atlas.at("texelRule").get<std::string>(), "capped at 2000 texels");
    }
    fs::remove_all(bake);
  }
  fs::remove_all(scratchDir());
}

TEST(AtlasApp, FailsWithTheReason) {
  fs::create_directories(scratchDir());
  const fs::path out = scratchDir() / "out.txt";
  EXPECT_NE(run("/nonexistent/scene.gltf", out), 0);
  EXPECT_NE(readText(out).find("/nonexistent/scene.gltf"), std::string::npos) << readText(out);
  EXPECT_NE(run(kCornell.string() + " --padding -1", out), 0);
  EXPECT_EQ(run("--help", out), 0);
  EXPECT_NE(readText(out).find("--texel-size"), std::string::npos);
  fs::remove_all(scratchDir());
}

}  // namespace
}  // namespace bounce
