// The `vpls` file (engine/bake_folder/vpl_file.h): the documented byte layout, a bit-exact round
// trip, a refusal naming the file and the reason for each kind of damage, and its place in the bake
// folder (written and read with the rest when the Bake has VPLs, absent otherwise).
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "bake_folder/vpl_file.h"
#include "io/load_error.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

std::vector<Vpl> someVpls() {
  return {{{1.5f, -2.0f, 0.25f}, {0, 0, 1}, {0.5f, 0.25f, 1e-30f}, {0.0f, 9.0f, -1.0f}, 0u},
          {{-1e6f, 3.0e-7f, 7.0f},
           {0.6f, 0.0f, -0.8f},
           {kMaxVplFlux, 0.0f, 1.17549435e-38f},
           {1.5f, -2.0f, 0.25f},
           0u},
          {{0, 0, 0}, {0, -1, 0}, {1, 2, 3}, {-4.0f, kMaxBakeLength, 2.5f}, 4000000000u}};
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("bounce_vpl_file_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

uint32_t u32At(const std::vector<unsigned char>& b, std::size_t at) {
  return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (static_cast<uint32_t>(b[at + 3]) << 24);
}

// decodeVpls's message, or "" when it succeeds.
std::string decodeError(const std::vector<unsigned char>& bytes) {
  try {
    decodeVpls("dir/vpls", bytes);
  } catch (const LoadError& e) {
    EXPECT_EQ(e.file(), fs::path("dir/vpls"));
    return e.what();
  }
  return "";
}

TEST(VplFile, BytesFollowTheDocumentedLayout) {
  const std::vector<Vpl> vpls = someVpls();
  const std::vector<unsigned char> b = encodeVpls(vpls);
  ASSERT_EQ(b.size(), 16u + 52u * vpls.size());
  EXPECT_EQ(std::memcmp(b.data(), "BNCVPLS\0", 8), 0);
  EXPECT_EQ(u32At(b, 8), 2u);
  EXPECT_EQ(u32At(b, 12), 3u);
  // Second VPL: position at 16 + 52, normal 12 bytes on, flux 24, from 36, path 48;
  // little-endian f32 and u32.
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 68)), -1e6f);
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 68 + 12)), 0.6f);
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 68 + 20)), -0.8f);
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 68 + 24)), kMaxVplFlux);
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 68 + 36)), 1.5f);
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 68 + 44)), 0.25f);
  EXPECT_EQ(u32At(b, 68 + 48), 0u);
  EXPECT_EQ(u32At(b, 120 + 48), 4000000000u);
}

TEST(VplFile, RoundTripIsBitExact) {
  const fs::path file = freshDir("roundtrip") / "vpls";
  for (const std::vector<Vpl>& vpls : {someVpls(), std::vector<Vpl>{}}) {
    writeVplFile(file, vpls);
    const std::vector<Vpl> back = readVplFile(file);
    ASSERT_EQ(back.size(), vpls.size());
    for (std::size_t i = 0; i < vpls.size(); ++i) {
      EXPECT_EQ(back[i].position, vpls[i].position);
      EXPECT_EQ(back[i].normal, vpls[i].normal);
      EXPECT_EQ(back[i].flux, vpls[i].flux);
      EXPECT_EQ(back[i].from, vpls[i].from);
      EXPECT_EQ(back[i].path, vpls[i].path);
    }
  }
}

TEST(VplFile, DamagedFilesAreRefusedWithTheFileAndTheReason) {
  const std::vector<unsigned char> good = encodeVpls(someVpls());
  ASSERT_EQ(decodeError(good), "");
  const auto damaged = [&](auto change) {
    std::vector<unsigned char> b = good;
    change(b);
    return decodeError(b);
  };
  const auto putF32 = [](std::vector<unsigned char>& b, std::size_t at, float v) {
    const uint32_t u = std::bit_cast<uint32_t>(v);
    for (int i = 0; i < 4; ++i) b[at + i] = static_cast<unsigned char>(u >> (8 * i));
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const struct {
    const char* reason;
    std::string message;
  } cases[] = {
      {"truncated", decodeError({good.begin(), good.begin() + 10})},
      {"bad magic", damaged([](auto& b) { b[3] = 'X'; })},
      {"format version 1, this build reads version 2: rebake", damaged([](auto& b) { b[8] = 1; })},
      {"4 VPLs announced need 224 bytes, the file has 172", damaged([](auto& b) { b[12] = 4; })},
      {"the file has 173", damaged([](auto& b) { b.push_back(0); })},
      {"VPL 1: position is not finite", damaged([&](auto& b) { putF32(b, 68 + 4, nan); })},
      {"VPL 0: normal is not a unit vector", damaged([&](auto& b) { putF32(b, 16 + 20, 0.9f); })},
      {"VPL 2: flux is negative", damaged([&](auto& b) { putF32(b, 120 + 28, -1.0f); })},
      {"VPL 2: flux is negative or not finite",
       damaged([&](auto& b) { putF32(b, 120 + 32, std::numeric_limits<float>::infinity()); })},
      {"VPL 1: path segment start is not finite",
       damaged([&](auto& b) { putF32(b, 68 + 40, nan); })},
      // Finite but beyond the documented ranges: NaN or a 14 % shift in the frame otherwise.
      {"VPL 1: flux is over 1e+09 W", damaged([&](auto& b) { putF32(b, 68 + 24, 3e38f); })},
      {"VPL 1: position is not finite or beyond 1e+06 m",
       damaged([&](auto& b) { putF32(b, 68 + 4, 1e30f); })},
      {"VPL 1: path segment start is not finite or beyond 1e+06 m",
       damaged([&](auto& b) { putF32(b, 68 + 40, -1e30f); })},
      {"VPL 1: path index 7 is smaller than the previous VPL's 9", damaged([&](auto& b) {
         b[16 + 48] = 9;
         b[68 + 48] = 7;
       })},
  };
  for (const auto& c : cases) {
    EXPECT_NE(c.message.find("dir/vpls: "), std::string::npos) << c.message;
    EXPECT_NE(c.message.find(c.reason), std::string::npos)
        << "expected '" << c.reason << "' in: " << c.message;
  }
  try {
    readVplFile(freshDir("missing") / "vpls");
    FAIL() << "a missing file was read";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
  }
}

// A bake with VPLs writes <dir>/vpls and reads them back; one without has no such file.
TEST(VplFile, TravelsWithTheBakeFolder) {
  Scene scene;
  Bake bake;
  bake.layout.width = 1;
  bake.layout.height = 1;
  bake.layout.texelSize = 1.0f;
  bake.irradiance = Image(1, 1);
  bake.manifest.sceneHash = sceneContentHash(scene);
  bake.manifest.atlas.width = bake.manifest.atlas.height = 1;
  const fs::path dir = freshDir("folder") / "scene.bake";
  writeBake(dir, bake);
  EXPECT_FALSE(fs::exists(dir / "vpls"));
  EXPECT_FALSE(readBake(dir, scene).vpls.has_value());
  bake.vpls = someVpls();
  bake.manifest.vpls = BakeManifest::Vpls{.count = bake.vpls->size()};
  writeBake(dir, bake);
  ASSERT_TRUE(fs::exists(dir / "vpls"));
  const Bake back = readBake(dir, scene);
  ASSERT_TRUE(back.vpls.has_value());
  ASSERT_EQ(back.vpls->size(), 3u);
  EXPECT_EQ((*back.vpls)[1].flux, someVpls()[1].flux);
}

}  // namespace
}  // namespace bounce
