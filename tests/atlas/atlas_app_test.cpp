// bounce-atlas end to end: the report, the picture and the exit codes.
#include <gtest/gtest.h>

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
