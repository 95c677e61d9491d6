// The panel's lines about a bake (bake_folder/bake_facts.h): figures from the layout and bake.json,
// its age from bake.json's time; figures bake.json lacks are left out, not shown as zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "bake_folder/bake_facts.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

bool hasLine(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

Bake bakeWithManifest(const BakeManifest& manifest) {
  Bake bake;
  bake.layout.width = 276;
  bake.layout.height = 72;
  bake.layout.texelSize = 0.01087f;
  bake.layout.utilisation = 0.849f;
  bake.layout.chartCount = 16;
  bake.manifest = manifest;
  bake.vpls = std::vector<Vpl>(4095);
  return bake;
}

TEST(BakeFacts, LinesGiveTheManifestsFiguresAndTheAge) {
  const fs::path dir = fs::temp_directory_path() / "bounce_bake_facts_test.bake";
  fs::create_directories(dir);
  BakeManifest manifest;
  manifest.settingsHash = "0123456789abcdef";  // made by bounce-bake
  // bake.json's copies of the atlas figures have no hash of their own: the panel shows layout.bin's
  // (hashed), so these do not reach it.
  manifest.atlas.utilisation = 0.2;
  manifest.atlas.charts = 3;
  manifest.samples.perTexelMean = 219.4;
  manifest.estimatedError = {.mean = 0.0969, .p95 = 0.0998, .target = 0.1};
  manifest.measured.seconds.total = 4.71;
  const Bake bake = bakeWithManifest(manifest);
  fs::path json = dir / "bake.json";
  std::ofstream(json) << manifestText(bake.manifest);
  fs::last_write_time(json, fs::file_time_type::clock::now() - std::chrono::hours(3));
  const std::vector<std::string> lines = bakeFactLines(bakeFacts(bake, dir));
  EXPECT_TRUE(hasLine(lines, dir.string()));
  EXPECT_TRUE(hasLine(lines, "atlas 276 x 72 texels, 85% used, 16 charts"));
  EXPECT_TRUE(hasLine(lines, "texel 1.09 cm"));
  EXPECT_TRUE(hasLine(lines, "219 samples per texel (mean)"));
  EXPECT_TRUE(hasLine(lines, "estimated error 9.7% mean, 10.0% p95 (target 10.0%)"));
  EXPECT_TRUE(hasLine(lines, "4095 VPLs"));
  EXPECT_TRUE(hasLine(lines, "baked in 4.7 s"));
  EXPECT_TRUE(hasLine(lines, "written 3 h ago"));
  fs::remove_all(dir);
}

TEST(BakeFacts, AHandMadeManifestLeavesItsFiguresOut) {
  const Bake bake = bakeWithManifest(BakeManifest{});
  const std::vector<std::string> lines = bakeFactLines(bakeFacts(bake, "/nowhere/x.bake"));
  EXPECT_TRUE(hasLine(lines, "atlas 276 x 72 texels"));
  for (const std::string& line : lines) {
    EXPECT_EQ(line.find("error"), std::string::npos) << line;
    EXPECT_EQ(line.find("samples"), std::string::npos) << line;
    EXPECT_EQ(line.find("written"), std::string::npos) << line;
  }
}

TEST(BakeFacts, AgeReadsInItsUnit) {
  EXPECT_EQ(ageText(12.0), "12 s");
  EXPECT_EQ(ageText(240.0), "4 min");
  EXPECT_EQ(ageText(3.0 * 3600.0), "3 h");
  EXPECT_EQ(ageText(2.0 * 86400.0), "2 days");
}

}  // namespace
}  // namespace bounce
