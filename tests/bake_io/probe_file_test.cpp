// The `probes.bin` file (engine/bake_folder/probe_file.h): the documented byte layout, a bit-exact
// round trip, a refusal naming the file and the reason for each check, and its place in the bake
// folder (recorded and hashed in bake.json; a grid only around a static instance without a region).
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "bake_folder/bake_input_file.h"
#include "bake_folder/probe_file.h"
#include "io/atomic_file.h"
#include "io/load_error.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

// Two grids: 2×2×2 around instance 1 (one triangle's 3 corners), 2×3×2 around instance 4
// (two triangles' 6 corners); the corners name 2 area lights and 1 punctual light.
IrradianceProbes someProbes() {
  IrradianceProbes p;
  p.grids.push_back({1, 0, {2, 2, 2}, {-1.0f, 0.5f, 2.0f}, {0.1f, 0.2f, 0.3f}, 0.025f, 0, 3});
  p.grids.push_back({4, 8, {2, 3, 2}, {3.0f, -2.0f, 0.0f}, {0.5f, 0.25f, 1e-3f}, 0.0f, 3, 6});
  p.visibility.lightCount = 2;
  p.visibility.punctualCount = 1;
  for (uint32_t i = 0; i < 9; ++i) {
    TexelVisibility corner;
    corner.light = {static_cast<uint16_t>(i % 3), kOtherLights, kNoLight, kNoLight};
    corner.visible = {0.125f * static_cast<float>(i % 8), 1.0f, 1.0f, 1.0f};
    p.visibility.corners.push_back(corner);
  }
  for (uint32_t i = 0; i < 20; ++i) {
    ProbeIrradiance probe;
    probe.sh[0] = {1.0f + i, 2.0f, 0.0f};
    probe.sh[1] = {-0.5f, 1e-30f, 3.0f};
    probe.sh[2] = {kMaxBakeIrradiance, -kMaxBakeIrradiance, 0.25f};
    probe.sh[3] = {0.0f, 0.125f * i, -7.0f};
    p.probes.push_back(probe);
  }
  return p;
}

uint32_t u32At(const std::vector<unsigned char>& b, std::size_t at) {
  return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (static_cast<uint32_t>(b[at + 3]) << 24);
}
void putU32(std::vector<unsigned char>& b, std::size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = static_cast<unsigned char>(v >> (8 * i));
}
void putF32(std::vector<unsigned char>& b, std::size_t at, float v) {
  putU32(b, at, std::bit_cast<uint32_t>(v));
}

// decodeProbes's message, or "" when it succeeds.
std::string decodeError(const std::vector<unsigned char>& bytes) {
  try {
    decodeProbes("dir/probes.bin", bytes);
  } catch (const LoadError& e) {
    EXPECT_EQ(e.file(), fs::path("dir/probes.bin"));
    return e.what();
  }
  return "";
}

TEST(ProbeFile, BytesFollowTheDocumentedLayout) {
  const IrradianceProbes p = someProbes();
  const std::vector<unsigned char> b = encodeProbes(p);
  ASSERT_EQ(b.size(), 32u + 56u * 2 + 48u * 20 + 24u * 9);
  EXPECT_EQ(std::memcmp(b.data(), "BNCPRBS\0", 8), 0);
  EXPECT_EQ(u32At(b, 8), kProbeFormatVersion);
  EXPECT_EQ(u32At(b, 12), 2u);
  EXPECT_EQ(u32At(b, 16), 20u);
  EXPECT_EQ(u32At(b, 20), 9u);                                 // corners
  EXPECT_EQ(u32At(b, 24), 2u);                                 // area lights they may name
  EXPECT_EQ(u32At(b, 28), 1u);                                 // punctual lights
  EXPECT_EQ(u32At(b, 32 + 56), 4u);                            // grid 1's instance
  EXPECT_EQ(u32At(b, 32 + 56 + 4), 8u);                        // its first probe
  EXPECT_EQ(u32At(b, 32 + 56 + 12), 3u);                       // its count along y
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 32 + 44)), 0.025f);  // grid 0's normal offset
  EXPECT_EQ(u32At(b, 32 + 56 + 48), 3u);                       // grid 1's first corner
  EXPECT_EQ(u32At(b, 32 + 56 + 52), 6u);                       // its corner count
  // Probe 3's E1−1 green, at 32 + 112 + 48·3 + 4·4.
  EXPECT_EQ(std::bit_cast<float>(u32At(b, 32 + 112 + 48 * 3 + 16)), 1e-30f);
  // Corner 5: its lights (u16) 2 and the other lights' mark, then its first V, 0.625.
  const std::size_t corner5 = 32 + 112 + 48 * 20 + 24 * 5;
  EXPECT_EQ(u32At(b, corner5), 2u | (uint32_t{kOtherLights} << 16));
  EXPECT_EQ(std::bit_cast<float>(u32At(b, corner5 + 8)), 0.625f);
}

TEST(ProbeFile, RoundTripIsBitExact) {
  const IrradianceProbes p = someProbes();
  EXPECT_EQ(decodeProbes("probes.bin", encodeProbes(p)), p);
  EXPECT_EQ(decodeProbes("probes.bin", encodeProbes(IrradianceProbes{})), IrradianceProbes{});
}

// One damaged copy per check of the reader, each refused with the file and its reason.
TEST(ProbeFile, EachDamageIsRefusedWithTheFileAndTheReason) {
  const std::vector<unsigned char> good = encodeProbes(someProbes());
  ASSERT_EQ(decodeError(good), "");
  constexpr std::size_t grid0 = 32, grid1 = 32 + 56, probe0 = 32 + 112;
  constexpr std::size_t corner0 = probe0 + 48 * 20;
  struct Case {
    const char* what;
    std::function<void(std::vector<unsigned char>&)> damage;
    const char* reason;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<Case> cases = {
      {"truncated header", [](auto& b) { b.resize(10); }, "truncated"},
      {"magic", [](auto& b) { b[3] = 'X'; }, "bad magic"},
      {"version", [](auto& b) { putU32(b, 8, 7); }, "format version 7"},
      {"size", [](auto& b) { b.push_back(0); }, "the file has"},
      {"probe count", [](auto& b) { putU32(b, 16, 19); }, "announced need"},
      {"order", [&](auto& b) { putU32(b, grid1, 1); }, "does not follow the previous grid's"},
      {"count under 2", [&](auto& b) { putU32(b, grid0 + 8, 1); }, "each must be in [2,"},
      {"count over the cap", [&](auto& b) { putU32(b, grid0 + 12, kMaxProbeGridCount + 1); },
       "each must be in [2,"},
      {"first", [&](auto& b) { putU32(b, grid1 + 4, 7); }, "the grids before it hold 8"},
      {"past the end", [&](auto& b) { putU32(b, grid1 + 16, 3); }, "run past the 20"},
      {"unused probes",
       [&](auto& b) {
         putU32(b, grid1 + 12, 2);  // 2×2×2: 16 of 20 used
       },
       "the grids hold 16 probes"},
      {"origin", [&](auto& b) { putF32(b, grid0 + 20, nan); }, "origin is not finite"},
      {"origin far", [&](auto& b) { putF32(b, grid0 + 24, 2e6f); }, "origin is not finite"},
      {"spacing", [&](auto& b) { putF32(b, grid1 + 36, 0.0f); }, "spacing is not in (0,"},
      {"normal offset", [&](auto& b) { putF32(b, grid0 + 44, -1.0f); }, "normal offset is not in"},
      {"coefficient", [&](auto& b) { putF32(b, probe0 + 48 * 5 + 20, nan); },
       "probe 5: a coefficient is not finite"},
      {"coefficient large", [&](auto& b) { putF32(b, probe0 + 40, 2e9f); },
       "a coefficient is not finite or beyond"},
      {"negative mean", [&](auto& b) { putF32(b, probe0 + 48 * 2 + 8, -1e-3f); },
       "probe 2: mean irradiance"},
      {"too many lights", [](auto& b) { putU32(b, 24, 70000); }, "at most 65533"},
      {"corner count", [](auto& b) { putU32(b, 20, 8); }, "announced need"},
      {"first corner", [&](auto& b) { putU32(b, grid1 + 48, 2); }, "the grids before it hold 3"},
      {"corners per triangle", [&](auto& b) { putU32(b, grid1 + 52, 5); }, "not 3 per triangle"},
      {"corners past the end", [&](auto& b) { putU32(b, grid1 + 52, 9); }, "run past the 9"},
      {"unused corners", [&](auto& b) { putU32(b, grid1 + 52, 3); }, "the grids hold 6 corners"},
      {"corner light", [&](auto& b) { b[corner0 + 24 * 4] = 3; }, "corner 4: light 3 of 3"},
      {"corner light twice",
       [&](auto& b) {
         b[corner0 + 2] = 0;
         b[corner0 + 3] = 0;
       },
       "corner 0: names light 0 twice"},
      {"corner V", [&](auto& b) { putF32(b, corner0 + 24 * 7 + 8, nan); },
       "corner 7: visible fraction is not in [0, 1]"},
      {"corner V over 1", [&](auto& b) { putF32(b, corner0 + 12, 1.5f); },
       "visible fraction is not in [0, 1]"},
  };
  for (const Case& c : cases) {
    std::vector<unsigned char> bad = good;
    c.damage(bad);
    const std::string message = decodeError(bad);
    EXPECT_NE(message.find("dir/probes.bin"), std::string::npos) << c.what << ": " << message;
    EXPECT_NE(message.find(c.reason), std::string::npos) << c.what << ": " << message;
  }
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("bounce_probe_file_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Instances: 0 static with a region, 1 static without, 2 dynamic.
Scene probeScene() {
  Scene s;
  s.source = "probe-scene.gltf";
  Mesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.normals.assign(3, {0, 0, 1});
  tri.indices = {0, 1, 2};
  s.meshes = {tri};
  s.materials = {Material{}};
  s.instances = {{"floor", 0, glm::mat4(1.0f), Mobility::Static},
                 {"cup", 0, glm::mat4(1.0f), Mobility::Static},
                 {"ball", 0, glm::mat4(1.0f), Mobility::Dynamic}};
  return s;
}

Bake probeBake(const Scene& scene, uint32_t gridInstance) {
  Bake bake;
  bake.layout.width = 4;
  bake.layout.height = 4;
  bake.layout.texelSize = 0.5f;
  bake.layout.instances = {{0, {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.1f, 0.9f}}}};
  bake.irradiance = Image(4, 4);
  bake.manifest.sceneHash = sceneContentHash(scene);
  bake.manifest.atlas.width = bake.manifest.atlas.height = 4;
  bake.manifest.atlas.regions = 1;
  IrradianceProbes probes;
  probes.grids.push_back({gridInstance, 0, {2, 2, 2}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}, 0.1f});
  probes.probes.assign(8, ProbeIrradiance{});
  bake.probes = probes;
  bake.manifest.probes = BakeManifest::Probes{.count = 8, .grids = 1};
  return bake;
}

std::string readBakeError(const fs::path& dir, const Scene& scene) {
  try {
    readBake(dir, scene);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

TEST(ProbeFile, TravelsWithTheBakeFolderRecordedAndHashed) {
  const Scene scene = probeScene();
  const fs::path dir = freshDir("folder") / "scene.bake";
  writeBake(dir, probeBake(scene, 1));
  ASSERT_TRUE(fs::exists(dir / "probes.bin"));
  const Bake back = readBake(dir, scene);
  ASSERT_TRUE(back.probes.has_value());
  EXPECT_EQ(*back.probes, *probeBake(scene, 1).probes);
  EXPECT_TRUE(back.manifest.files.contains("probes.bin"));
  // One byte changed: the hash bake.json records refuses it, naming the file.
  std::vector<unsigned char> bytes = readBakeInputFile(dir / "probes.bin");
  bytes[30] ^= 1;
  writeFileAtomically(dir / "probes.bin", bytes);
  const std::string message = readBakeError(dir, scene);
  EXPECT_NE(message.find("probes.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("damaged"), std::string::npos) << message;
}

TEST(ProbeFile, AGridAroundAnInstanceWithARegionOrADynamicOneIsRefused) {
  const Scene scene = probeScene();
  const fs::path dir = freshDir("instances") / "scene.bake";
  writeBake(dir, probeBake(scene, 0));
  std::string message = readBakeError(dir, scene);
  EXPECT_NE(message.find("probes.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("has a lightmap region"), std::string::npos) << message;
  writeBake(dir, probeBake(scene, 2));
  message = readBakeError(dir, scene);
  EXPECT_NE(message.find("is dynamic"), std::string::npos) << message;
  writeBake(dir, probeBake(scene, 3));
  message = readBakeError(dir, scene);
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
}

// The corners must be 3 per triangle of the instance's mesh and name the scene's lights.
TEST(ProbeFile, CornersThatAreNotTheMeshsOrNameOtherLightsAreRefused) {
  const Scene scene = probeScene();  // one triangle, no light
  const fs::path dir = freshDir("corners") / "scene.bake";
  Bake bake = probeBake(scene, 1);
  bake.probes->grids[0].cornerCount = 3;
  bake.probes->visibility.corners.assign(3, TexelVisibility{});
  writeBake(dir, bake);
  EXPECT_EQ(readBakeError(dir, scene), "");
  bake.probes->grids[0].cornerCount = 6;
  bake.probes->visibility.corners.assign(6, TexelVisibility{});
  writeBake(dir, bake);
  std::string message = readBakeError(dir, scene);
  EXPECT_NE(message.find("probes.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("6 visibility corners, its mesh 3"), std::string::npos) << message;
  bake.probes->grids[0].cornerCount = 3;
  bake.probes->visibility.corners.assign(3, TexelVisibility{});
  bake.probes->visibility.lightCount = 1;
  writeBake(dir, bake);
  message = readBakeError(dir, scene);
  EXPECT_NE(message.find("its corners name 1 static area and 0 punctual lights"), std::string::npos)
      << message;
}

TEST(ProbeFile, AManifestThatDisagreesIsRefusedWhenWritten) {
  const Scene scene = probeScene();
  Bake bake = probeBake(scene, 1);
  bake.manifest.probes->count = 9;
  EXPECT_THROW(writeBake(freshDir("disagree") / "scene.bake", bake), std::runtime_error);
  bake.manifest.probes.reset();
  EXPECT_THROW(writeBake(freshDir("disagree") / "scene.bake", bake), std::runtime_error);
}

}  // namespace
}  // namespace bounce
