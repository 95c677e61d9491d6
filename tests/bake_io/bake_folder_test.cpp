// The bake folder: round trip, the scene hash, every rejection of readBake, and the atomic
// replace of writeBake.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake_folder/bake_folder.h"
#include "bake_folder/vpl_clamp.h"
#include "image/image_io.h"
#include "io/load_error.h"

namespace fs = std::filesystem;
using namespace bounce;

namespace {

// Two meshes (a quad of 2 triangles, a single triangle), three instances: the quad static, the
// triangle dynamic, the triangle again static at another scale.
Scene testScene() {
  Scene s;
  s.source = "test-scene.gltf";
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  quad.normals.assign(4, {0, 1, 0});
  quad.indices = {0, 2, 1, 0, 3, 2};
  Mesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.normals.assign(3, {0, 0, 1});
  tri.indices = {0, 1, 2};
  tri.material = 1;
  s.meshes = {quad, tri};
  Material white;
  white.albedo = glm::vec3(0.8f);
  Material red;
  red.albedo = {0.7f, 0.1f, 0.1f};
  red.albedoTexture = 0;
  s.materials = {white, red};
  Texture t;
  t.width = 2;
  t.height = 1;
  t.texels = {{1, 1, 1}, {0.5f, 0.5f, 0.5f}};
  s.textures = {t};
  s.instances = {{"floor", 0, glm::mat4(1.0f), Mobility::Static},
                 {"mover", 1, glm::mat4(1.0f), Mobility::Dynamic},
                 {"big", 1, glm::mat4(2.0f), Mobility::Static}};
  s.instances[2].transform[3] = {0, 0, 0, 1};
  Light l;
  l.position = {0, 2, 0};
  l.intensity = {10, 10, 10};
  s.lights = {l};
  return s;
}

Bake testBake(const Scene& scene) {
  Bake b;
  b.layout.width = 16;
  b.layout.height = 8;
  b.layout.texelSize = 0.125f;
  b.layout.padding = 2;
  b.layout.chartCount = 3;
  b.layout.utilisation = 0.4375f;
  InstanceLightmapUv floor{0, {}};
  for (int i = 0; i < 6; ++i) floor.cornerUv.push_back({0.0625f * i + 1e-7f, 1.0f / (3 + i)});
  InstanceLightmapUv big{2, {{0.5f, 0.5f}, {0.9999999f, 0.5f}, {0.5f, 0.0000001f}}};
  b.layout.instances = {floor, big};
  b.irradiance = Image(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      b.irradiance.at(x, y) = {x * 0.3f + 1e-30f, y * 123.456f, 1.0f / (1 + x + 7 * y)};
  b.irradiance.at(0, 0) = {kMaxBakeIrradiance, 1.17549435e-38f, 0.0f};  // the extremes
  b.manifest.sceneHash = sceneContentHash(scene);
  b.manifest.atlas.width = 16;
  b.manifest.atlas.height = 8;
  b.manifest.atlas.regions = 2;
  return b;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("bounce_bake_io_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<unsigned char> readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& file, const std::vector<unsigned char>& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

BakeManifest readManifest(const fs::path& dir) {
  const std::vector<unsigned char> text = readBytes(dir / "bake.json");
  return parseManifest(dir / "bake.json", std::string(text.begin(), text.end()));
}

void writeManifest(const fs::path& dir, const BakeManifest& manifest) {
  std::ofstream(dir / "bake.json", std::ios::trunc) << manifestText(manifest);
}

// Records every file's size and hash in bake.json again, as a forger would: the check under test
// is then reached rather than the hash check that catches any edit first.
void restamp(const fs::path& dir) {
  BakeManifest manifest = readManifest(dir);
  manifest.files.clear();
  for (const char* name : {"layout.bin", "lightmap.exr", "error.exr", "vpls", "visibility.bin"})
    if (fs::is_regular_file(dir / name)) {
      const std::vector<unsigned char> bytes = readBytes(dir / name);
      manifest.files[name] = {bytes.size(), fnv1a64Hex(bytes)};
    }
  writeManifest(dir, manifest);
}

// readBake's message, or "" when it succeeds.
std::string readError(const fs::path& dir, const Scene& scene) {
  try {
    readBake(dir, scene);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

bool bitEqual(float a, float b) {
  return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}

void expectSameBake(const Bake& a, const Bake& b) {
  // The manifest round-trips whole; only its file records are writeBake's.
  BakeManifest written = a.manifest;
  written.files = b.manifest.files;
  EXPECT_EQ(manifestText(written), manifestText(b.manifest));
  EXPECT_EQ(a.layout.width, b.layout.width);
  EXPECT_EQ(a.layout.height, b.layout.height);
  EXPECT_TRUE(bitEqual(a.layout.texelSize, b.layout.texelSize));
  EXPECT_EQ(a.layout.padding, b.layout.padding);
  EXPECT_EQ(a.layout.chartCount, b.layout.chartCount);
  EXPECT_TRUE(bitEqual(a.layout.utilisation, b.layout.utilisation));
  ASSERT_EQ(a.layout.instances.size(), b.layout.instances.size());
  for (std::size_t i = 0; i < a.layout.instances.size(); ++i) {
    EXPECT_EQ(a.layout.instances[i].instance, b.layout.instances[i].instance);
    ASSERT_EQ(a.layout.instances[i].cornerUv.size(), b.layout.instances[i].cornerUv.size());
    for (std::size_t k = 0; k < a.layout.instances[i].cornerUv.size(); ++k) {
      EXPECT_TRUE(
          bitEqual(a.layout.instances[i].cornerUv[k].x, b.layout.instances[i].cornerUv[k].x));
      EXPECT_TRUE(
          bitEqual(a.layout.instances[i].cornerUv[k].y, b.layout.instances[i].cornerUv[k].y));
    }
  }
  ASSERT_EQ(a.irradiance.width, b.irradiance.width);
  ASSERT_EQ(a.irradiance.height, b.irradiance.height);
  for (std::size_t i = 0; i < a.irradiance.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_TRUE(bitEqual(a.irradiance.pixels[i][c], b.irradiance.pixels[i][c])) << i << " " << c;
}

int countEntries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(BakeFolder, RoundTripIsBitExact) {
  const Scene scene = testScene();
  const Bake bake = testBake(scene);
  const fs::path dir = freshDir("roundtrip") / "scene.bake";
  writeBake(dir, bake);
  EXPECT_TRUE(fs::exists(dir / "bake.json"));
  EXPECT_TRUE(fs::exists(dir / "lightmap.exr"));
  EXPECT_TRUE(fs::exists(dir / "layout.bin"));
  expectSameBake(bake, readBake(dir, scene));
  // Nothing but the folder itself is left next to it.
  EXPECT_EQ(countEntries(dir.parent_path()), 1);
}

// error.exr: each texel's relative error (or kNoErrorEstimate) comes back bit for bit; a bake
// without it reads back without it.
TEST(BakeFolder, ErrorMapRoundTripsAndIsOptional) {
  const Scene scene = testScene();
  Bake bake = testBake(scene);
  const fs::path dir = freshDir("error_map") / "scene.bake";
  writeBake(dir, bake);
  EXPECT_FALSE(fs::exists(dir / "error.exr"));
  EXPECT_FALSE(readBake(dir, scene).relativeError.has_value());
  bake.relativeError = Image(16, 8, glm::vec3(kNoErrorEstimate));
  for (int x = 0; x < 16; ++x) bake.relativeError->at(x, 3) = glm::vec3(0.013f * x);
  writeBake(dir, bake);
  const Bake back = readBake(dir, scene);
  ASSERT_TRUE(back.relativeError.has_value());
  ASSERT_EQ(back.relativeError->pixels.size(), bake.relativeError->pixels.size());
  for (std::size_t i = 0; i < back.relativeError->pixels.size(); ++i)
    EXPECT_TRUE(bitEqual(back.relativeError->pixels[i].g, bake.relativeError->pixels[i].g)) << i;
  bake.relativeError = Image(8, 8);
  EXPECT_THROW(writeBake(dir, bake), std::runtime_error);
}

TEST(BakeFolder, RewriteReplacesTheWholeFolder) {
  const Scene scene = testScene();
  const fs::path dir = freshDir("rewrite") / "scene.bake";
  writeBake(dir, testBake(scene));
  std::ofstream(dir / "stale-file") << "from an older bake";
  Bake second = testBake(scene);
  second.irradiance.at(3, 3) = {42, 43, 44};
  writeBake(dir, second);
  expectSameBake(second, readBake(dir, scene));
  EXPECT_FALSE(fs::exists(dir / "stale-file"));
  EXPECT_EQ(countEntries(dir.parent_path()), 1);
}

// A write that fails half-way (the lightmap hits the file size limit after bake.json and
// layout.bin were written) leaves the previous bake readable and no temporary folder behind.
TEST(BakeFolder, FailedWriteLeavesThePreviousBake) {
  const Scene scene = testScene();
  const fs::path dir = freshDir("atomic") / "scene.bake";
  const Bake first = testBake(scene);
  writeBake(dir, first);

  Bake big = testBake(scene);
  big.layout.width = big.layout.height = 256;
  big.manifest.atlas.width = big.manifest.atlas.height = 256;
  big.irradiance = Image(256, 256);
  uint32_t bits = 12345;  // an xorshift pattern: incompressible, so the EXR stays large
  for (glm::vec3& p : big.irradiance.pixels)
    for (int c = 0; c < 3; ++c) {
      bits ^= bits << 13, bits ^= bits >> 17, bits ^= bits << 5;
      p[c] = std::bit_cast<float>(0x3f800000u | (bits >> 9));
    }

  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of a signal
  rlimit small = saved;
  small.rlim_cur = 16 * 1024;  // the manifest and layout fit, the ~700 KB lightmap does not
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    writeBake(dir, big);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previousHandler);

  EXPECT_NE(message.find("lightmap.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  expectSameBake(first, readBake(dir, scene));
  EXPECT_EQ(countEntries(dir.parent_path()), 1);
}

TEST(BakeFolder, WriterRefusesAnIncompleteManifestOrAMismatchedLightmap) {
  const Scene scene = testScene();
  const fs::path dir = freshDir("writer") / "scene.bake";
  const auto writeError = [&](const Bake& b) -> std::string {
    try {
      writeBake(dir, b);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  Bake b = testBake(scene);
  b.manifest.sceneHash.clear();
  EXPECT_NE(writeError(b).find("sceneHash"), std::string::npos);
  b = testBake(scene);
  b.manifest.formatVersion = 99;
  EXPECT_NE(writeError(b).find("formatVersion 99"), std::string::npos);
  b = testBake(scene);
  b.manifest.atlas.width = 17;
  EXPECT_NE(writeError(b).find("bake.json's atlas is 17x8"), std::string::npos);
  b = testBake(scene);
  b.vpls = std::vector<Vpl>(2);
  EXPECT_NE(writeError(b).find("bake.json describes no VPLs"), std::string::npos);
  b = testBake(scene);
  b.irradiance = Image(8, 8);
  EXPECT_NE(writeError(b).find("does not match"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir));
  EXPECT_EQ(countEntries(dir.parent_path()), 0);
}

// ---- every rejection names the file and the reason

class BakeRejection : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshDir(::testing::UnitTest::GetInstance()->current_test_info()->name()) / "s.bake";
    writeBake(dir_, testBake(scene_));
    ASSERT_EQ(readError(dir_, scene_), "");
  }
  void expectRefused(const std::string& file, const std::string& reason) {
    const std::string message = readError(dir_, scene_);
    EXPECT_NE(message.find((dir_ / file).string()), std::string::npos) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
  }
  void rewriteLayout(std::function<void(std::vector<unsigned char>&)> edit) {
    std::vector<unsigned char> bytes = readBytes(dir_ / "layout.bin");
    edit(bytes);
    writeBytes(dir_ / "layout.bin", bytes);
    restamp(dir_);
  }
  void rewriteManifest(std::function<void(BakeManifest&)> edit) {
    BakeManifest manifest = readManifest(dir_);
    edit(manifest);
    writeManifest(dir_, manifest);
  }
  // Writes a bake whose layout was edited (the writer does not know the scene).
  void writeWithLayout(std::function<void(LightmapLayout&)> edit) {
    Bake b = testBake(scene_);
    edit(b.layout);
    writeBake(dir_, b);
  }
  Scene scene_ = testScene();
  fs::path dir_;
};

TEST_F(BakeRejection, MissingFolder) {
  const std::string message = readError(dir_.parent_path() / "nothing.bake", scene_);
  EXPECT_NE(message.find("nothing.bake: no bake folder"), std::string::npos) << message;
}

TEST_F(BakeRejection, MissingFiles) {
  for (const char* file : {"bake.json", "layout.bin", "lightmap.exr"}) {
    writeBake(dir_, testBake(scene_));
    fs::remove(dir_ / file);
    expectRefused(file, "missing");
  }
}

// A FIFO (or a device, a directory) in place of a bake file is refused before it is opened:
// opening a FIFO for reading blocks until a writer appears. The alarm turns the hang the bug
// gives into a failure within 20 s instead of CTest's timeout.
TEST_F(BakeRejection, FilesThatAreNotRegularAreRefusedWithoutBlocking) {
  Bake withVpls = testBake(scene_);
  withVpls.vpls = std::vector<Vpl>{{{0, 1, 0}, {0, -1, 0}, {0.1f, 0.2f, 0.3f}}};
  withVpls.manifest.vpls = BakeManifest::Vpls{.count = 1};
  for (const char* file : {"bake.json", "layout.bin", "lightmap.exr", "vpls"}) {
    writeBake(dir_, withVpls);
    fs::remove(dir_ / file);
    ASSERT_EQ(::mkfifo((dir_ / file).c_str(), 0600), 0) << file;
    ::alarm(20);
    expectRefused(file, "is a FIFO");
    ::alarm(0);
  }
  writeBake(dir_, withVpls);
  fs::remove(dir_ / "layout.bin");
  fs::create_directory(dir_ / "layout.bin");
  expectRefused("layout.bin", "is a directory");
}

// bake.json nested 100000 deep would overflow the stack inside the recursive JSON parser.
TEST_F(BakeRejection, ManifestNestedTooDeep) {
  std::ofstream(dir_ / "bake.json")
      << "{\"x\": " << std::string(100000, '[') << std::string(100000, ']') << "}";
  expectRefused("bake.json", "JSON nests arrays/objects deeper than 64");
}

TEST_F(BakeRejection, ManifestNotJson) {
  std::ofstream(dir_ / "bake.json") << "{\"formatVersion\": 1,";
  expectRefused("bake.json", "not JSON");
}

TEST_F(BakeRejection, ManifestFormatVersion) {
  std::ofstream(dir_ / "bake.json") << nlohmann::json{{"formatVersion", kBakeFormatVersion + 1},
                                                      {"sceneHash", sceneContentHash(scene_)}};
  expectRefused("bake.json", "format version " + std::to_string(kBakeFormatVersion + 1) +
                                 ", this build reads version " +
                                 std::to_string(kBakeFormatVersion));
  // 2^32 + 2 would read as 2 through a 32-bit int; 2.0 is not an exact integer.
  std::ofstream(dir_ / "bake.json", std::ios::trunc)
      << R"({"formatVersion": 4294967298, "sceneHash": "x"})";
  expectRefused("bake.json", "format version 4294967298, this build reads version 2: rebake");
  std::ofstream(dir_ / "bake.json", std::ios::trunc)
      << R"({"formatVersion": 2.0, "sceneHash": "x"})";
  expectRefused("bake.json", "no integer \"formatVersion\"");
}

// bake.json says which light pick next-event estimation used; bake.json files written before it
// did mean "power" (the only pick then); anything else is refused.
TEST_F(BakeRejection, ManifestLightChoice) {
  rewriteManifest([](BakeManifest& m) { m.settings.lightChoice = LightChoice::ByPlace; });
  EXPECT_EQ(readManifest(dir_).settings.lightChoice, LightChoice::ByPlace);
  nlohmann::json json = nlohmann::json::parse(manifestText(readManifest(dir_)));
  json["settings"].erase("lightChoice");
  std::ofstream(dir_ / "bake.json", std::ios::trunc) << json.dump();
  EXPECT_EQ(readManifest(dir_).settings.lightChoice, LightChoice::ByPower);
  json["settings"]["lightChoice"] = "brightest";
  std::ofstream(dir_ / "bake.json", std::ios::trunc) << json.dump();
  expectRefused("bake.json", "settings.lightChoice is \"brightest\", not place or power");
}

// ---- a stale bake: the folder, both hashes, and why where bake.json or the files' times tell

// Rewrites bake.json with the optional fields bounce-bake writes: the scene file's name and the
// per-part hashes of `baked`.
void writeManifestWithParts(const fs::path& dir, const Scene& baked, const std::string& file) {
  const SceneHash hash = sceneHash(baked);
  BakeManifest manifest = readManifest(dir);
  manifest.sceneHash = hash.whole;
  manifest.scene = file;
  for (std::size_t i = 0; i < hash.parts.size(); ++i)
    manifest.sceneParts[kScenePartNames[i]] = hash.parts[i];
  writeManifest(dir, manifest);
}

TEST_F(BakeRejection, StaleBakeGivesBothHashes) {
  const std::string baked = sceneContentHash(scene_);
  scene_.materials[0].albedo = glm::vec3(0.5f);
  expectRefused("bake.json", "stale bake: it does not match the scene");
  expectRefused("bake.json", "its scene hash is " + baked + ", test-scene.gltf hashes to " +
                                 sceneContentHash(scene_) + ": rebake");
  // testBake's manifest has no per-part hashes: it cannot tell more.
  expectRefused("bake.json", "records no per-part hashes");
}

TEST_F(BakeRejection, StaleBakeNamesTheChangedParts) {
  writeManifestWithParts(dir_, scene_, "test-scene.gltf");
  ASSERT_EQ(readError(dir_, scene_), "");
  scene_.lights[0].position.x += 0.25f;
  expectRefused("bake.json", "(the scene changed since the bake: its lights differ)");
  scene_.materials[1].doubleSided = true;
  expectRefused("bake.json", "(the scene changed since the bake: its materials and lights differ)");
  scene_.meshes[0].positions[0].y = 1.0f;
  expectRefused("bake.json",
                "(the scene changed since the bake: its meshes, materials and lights differ)");
}

TEST_F(BakeRejection, StaleBakeOfAnotherSceneFile) {
  writeManifestWithParts(dir_, scene_, "other.gltf");
  scene_.lights[0].irradiance = {1, 1, 1};
  expectRefused("bake.json", "(it was made for another scene, other.gltf)");
}

TEST_F(BakeRejection, StaleBakeOfASceneFileModifiedAfterIt) {
  const fs::path sceneFile = dir_.parent_path() / "test-scene.gltf";
  std::ofstream(sceneFile) << "{}";
  scene_.source = sceneFile.string();
  fs::last_write_time(dir_ / "bake.json", fs::last_write_time(sceneFile) - std::chrono::hours(1));
  ASSERT_EQ(readError(dir_, scene_), "");  // the times alone do not make a bake stale
  scene_.lights[0].intensity = {1, 2, 3};
  expectRefused("bake.json", "(the scene changed since the bake; " + sceneFile.string() +
                                 " was modified after it)");
}

TEST_F(BakeRejection, LayoutBadMagic) {
  rewriteLayout([](auto& bytes) { bytes[0] = 'X'; });
  expectRefused("layout.bin", "bad magic");
}

TEST_F(BakeRejection, LayoutFormatVersion) {
  rewriteLayout([](auto& bytes) { bytes[8] = static_cast<unsigned char>(kBakeFormatVersion + 1); });
  expectRefused("layout.bin", "format version " + std::to_string(kBakeFormatVersion + 1));
}

TEST_F(BakeRejection, LayoutTruncatedAnywhere) {
  const std::vector<unsigned char> whole = readBytes(dir_ / "layout.bin");
  for (std::size_t size = 0; size < whole.size(); ++size) {
    writeBytes(dir_ / "layout.bin", {whole.begin(), whole.begin() + static_cast<long>(size)});
    restamp(dir_);
    expectRefused("layout.bin", "truncated");
  }
}

TEST_F(BakeRejection, LayoutTrailingBytes) {
  rewriteLayout([](auto& bytes) { bytes.push_back(0); });
  expectRefused("layout.bin", "1 bytes after the last instance region");
}

TEST_F(BakeRejection, LayoutHugeCountIsTruncationNotAnAllocation) {
  rewriteLayout([](auto& bytes) { std::memset(bytes.data() + 36, 0xff, 4); });  // instance count
  expectRefused("layout.bin", "truncated");
}

TEST_F(BakeRejection, InstanceOutOfRange) {
  writeWithLayout([](LightmapLayout& l) { l.instances[1].instance = 3; });
  expectRefused("layout.bin", "instance 3 out of range (the scene has 3 instances)");
}

TEST_F(BakeRejection, DynamicInstanceHasARegion) {
  writeWithLayout([](LightmapLayout& l) { l.instances[1].instance = 1; });
  expectRefused("layout.bin", "is dynamic");
}

TEST_F(BakeRejection, RegionsOutOfOrder) {
  writeWithLayout([](LightmapLayout& l) { std::swap(l.instances[0], l.instances[1]); });
  expectRefused("layout.bin", "not in increasing order");
}

TEST_F(BakeRejection, CornerCountIsNotThreePerTriangle) {
  writeWithLayout([](LightmapLayout& l) { l.instances[0].cornerUv.pop_back(); });
  expectRefused("layout.bin", "has 5 corner UVs, its mesh needs 3 × 2");
}

// Atlas UVs lie in [0, 1]² (lightmap_layout.h): NaN, 1e30 (an undefined float-to-int cast in
// the renderer) and one flipped exponent bit are refused.
TEST_F(BakeRejection, CornerUvOutsideTheAtlas) {
  for (const float bad : {NAN, INFINITY, 1e30f, -1e-6f, 1.0001f, 2.0f}) {
    writeWithLayout([&](LightmapLayout& l) { l.instances[1].cornerUv[2].y = bad; });
    expectRefused("layout.bin", "outside [0, 1]");
  }
}

TEST_F(BakeRejection, LightmapSizeDisagreesWithLayout) {
  writeExr(dir_ / "lightmap.exr", Image(16, 9));
  restamp(dir_);
  expectRefused("lightmap.exr", "is 16x9, layout.bin says 16x8");
}

TEST_F(BakeRejection, ErrorMapSizeDisagreesWithLayout) {
  writeExr(dir_ / "error.exr", Image(8, 8));
  restamp(dir_);
  expectRefused("error.exr", "is 8x8, layout.bin says 16x8");
}

TEST_F(BakeRejection, ErrorMapWithANegativeOrUnequalTexel) {
  Image error(16, 8, glm::vec3(0.1f));
  error.at(3, 2) = glm::vec3(-0.5f);
  writeExr(dir_ / "error.exr", error);
  restamp(dir_);
  expectRefused("error.exr", "each texel is one relative error");
  error.at(3, 2) = glm::vec3(0.1f, 0.2f, 0.1f);
  writeExr(dir_ / "error.exr", error);
  restamp(dir_);
  expectRefused("error.exr", "each texel is one relative error");
  error.at(3, 2) = glm::vec3(NAN);
  writeExr(dir_ / "error.exr", error);
  restamp(dir_);
  expectRefused("error.exr", "each texel is one relative error");
  error.at(3, 2) = glm::vec3(kNoErrorEstimate);
  writeExr(dir_ / "error.exr", error);
  restamp(dir_);
  EXPECT_EQ(readError(dir_, scene_), "");
}

TEST_F(BakeRejection, LightmapNotAnExr) {
  std::ofstream(dir_ / "lightmap.exr") << "not an exr";
  restamp(dir_);
  expectRefused("lightmap.exr", "cannot read EXR");
}

// ---- the files are tied to the manifest: their sizes and hashes, and what it says of them

// Any edit of a file, even one byte or one that keeps its size and every range (an all-black
// lightmap, two regions swapped), is refused by the hash bake.json records.
TEST_F(BakeRejection, DamagedOrReplacedFileIsRefusedByItsHash) {
  Bake bake = testBake(scene_);
  bake.vpls = std::vector<Vpl>{{{0, 1, 0}, {0, -1, 0}, {0.1f, 0.2f, 0.3f}}};
  bake.manifest.vpls = BakeManifest::Vpls{.count = 1};
  bake.relativeError = Image(16, 8, glm::vec3(0.1f));
  for (const char* file : {"layout.bin", "lightmap.exr", "error.exr", "vpls"}) {
    writeBake(dir_, bake);
    std::vector<unsigned char> bytes = readBytes(dir_ / file);
    bytes[bytes.size() / 2] ^= 0x10;
    writeBytes(dir_ / file, bytes);
    expectRefused(file, "damaged or another bake's: rebake");
    bytes.pop_back();
    writeBytes(dir_ / file, bytes);
    expectRefused(file, "bytes, bake.json records");
  }
  writeBake(dir_, bake);
  writeExr(dir_ / "lightmap.exr", Image(16, 8));  // all black
  expectRefused("lightmap.exr", "rebake");
  Bake swapped = bake;  // the two regions' UVs exchanged where their sizes allow
  std::swap(swapped.layout.instances[0].cornerUv[0], swapped.layout.instances[1].cornerUv[0]);
  const fs::path other = dir_.parent_path() / "other.bake";
  writeBake(other, swapped);
  fs::copy_file(other / "layout.bin", dir_ / "layout.bin", fs::copy_options::overwrite_existing);
  expectRefused("layout.bin", "its hash is");
}

// The layout, lightmap and VPLs of another bake under this bake's manifest.
TEST_F(BakeRejection, FilesOfAnotherBakeAreRefused) {
  Bake other = testBake(scene_);
  other.irradiance.at(5, 5) = {1, 2, 3};
  const fs::path otherDir = dir_.parent_path() / "other.bake";
  writeBake(otherDir, other);
  fs::copy_file(otherDir / "lightmap.exr", dir_ / "lightmap.exr",
                fs::copy_options::overwrite_existing);
  expectRefused("lightmap.exr", "damaged");
  writeBake(dir_, testBake(scene_));
  other.vpls = std::vector<Vpl>(1, Vpl{{0, 1, 0}, {0, -1, 0}, {1, 1, 1}});
  other.manifest.vpls = BakeManifest::Vpls{.count = 1};
  writeBake(otherDir, other);
  fs::copy_file(otherDir / "vpls", dir_ / "vpls");
  expectRefused("vpls", "not recorded in bake.json");
}

TEST_F(BakeRejection, ManifestWithoutFileRecordsAsksForARebake) {
  std::string text = manifestText(readManifest(dir_));
  text.replace(text.find("\"files\""), 7, "\"filez\"");
  std::ofstream(dir_ / "bake.json", std::ios::trunc) << text;
  expectRefused("bake.json", "no \"files\" (the sizes and hashes of the folder's files): rebake");
  writeBake(dir_, testBake(scene_));
  rewriteManifest([](BakeManifest& m) { m.files.erase("lightmap.exr"); });
  expectRefused("bake.json", "\"files\" does not record lightmap.exr");
}

// NaN, infinite, negative or huge irradiance would reach the frame (one NaN texel puts NaN
// pixels in it).
TEST_F(BakeRejection, IrradianceOutOfRange) {
  for (const float bad : {NAN, INFINITY, -1.0f, 3e38f, 2.0f * kMaxBakeIrradiance}) {
    Image irradiance = testBake(scene_).irradiance;
    irradiance.at(4, 2).g = bad;
    writeExr(dir_ / "lightmap.exr", irradiance);
    restamp(dir_);
    expectRefused("lightmap.exr", "texel (4, 2) holds irradiance");
  }
}

// What bake.json says of the files must hold, forged hashes or not: the atlas size, the region
// count (a layout with a region missing), the VPL count.
TEST_F(BakeRejection, FilesDisagreeingWithTheManifest) {
  rewriteManifest([](BakeManifest& m) { m.atlas.width = 20; });
  expectRefused("layout.bin", "is 16x8, bake.json's atlas is 20x8");
  writeBake(dir_, testBake(scene_));
  Bake oneRegion = testBake(scene_);
  oneRegion.layout.instances.pop_back();
  oneRegion.manifest.atlas.regions = 1;
  const fs::path other = dir_.parent_path() / "other.bake";
  writeBake(other, oneRegion);
  fs::copy_file(other / "layout.bin", dir_ / "layout.bin", fs::copy_options::overwrite_existing);
  restamp(dir_);
  expectRefused("layout.bin", "has 1 instance regions, bake.json's atlas has 2");
  Bake withVpls = testBake(scene_);
  withVpls.vpls = std::vector<Vpl>(2, Vpl{{0, 1, 0}, {0, -1, 0}, {1, 1, 1}});
  withVpls.manifest.vpls = BakeManifest::Vpls{.count = 2};
  writeBake(dir_, withVpls);
  rewriteManifest([](BakeManifest& m) { m.vpls->count = 3; });
  expectRefused("vpls", "holds 2 VPLs, bake.json says 3");
}

// A clamp distance that overflows a float, or a field of the wrong type, is refused by name.
TEST_F(BakeRejection, ManifestFieldsOutOfRange) {
  Bake withVpls = testBake(scene_);
  withVpls.vpls = std::vector<Vpl>(1, Vpl{{0, 1, 0}, {0, -1, 0}, {1, 1, 1}});
  withVpls.manifest.vpls = BakeManifest::Vpls{.count = 1};
  writeBake(dir_, withVpls);
  // The clamp bounce-bake writes for the scene's static area and one VPL (vpl_clamp.h).
  const double rule = vplClampDistance(staticSurfaceArea(scene_), 1);
  rewriteManifest([&](BakeManifest& m) { m.vpls->clampDistance = rule; });
  EXPECT_EQ(readError(dir_, scene_), "");
  rewriteManifest([](BakeManifest& m) { m.vpls->clampDistance = 1e39; });
  expectRefused("bake.json", "\"vpls.clampDistance\" is 1e+39, out of range [0, 1e+06]");
  writeBake(dir_, withVpls);
  std::string text = manifestText(readManifest(dir_));
  text.replace(text.find("\"width\": 16"), 11, "\"width\": 4294967312");
  std::ofstream(dir_ / "bake.json", std::ios::trunc) << text;
  expectRefused("bake.json", "\"atlas.width\" is 4294967312, out of range 1..65536");
}
