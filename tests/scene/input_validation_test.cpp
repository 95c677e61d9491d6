// One test per class of bad input that used to crash, hang or load as a wrong scene:
// each now gives one LoadError naming the file and the limit or rule (docs/input_limits.md).
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>
#include <sys/stat.h>

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <future>
#include <random>

#include "expect_load_error.h"
#include "gltf_fixture.h"
#include "scene/input_limits.h"
#include "scene/load.h"

namespace bounce {
namespace {

using test::expectLoadError;
using test::GltfFixture;
using test::TempDir;

// loadScene(path) on another thread; a load still blocked after 10 s is a failure, and the
// FIFO `fifo` is then opened for writing to release it.
void expectLoadErrorWithoutBlocking(const std::filesystem::path& path, const std::string& reason,
                                    const std::filesystem::path& fifo) {
  auto load = std::async(std::launch::async, [&] { expectLoadError(path, reason); });
  if (load.wait_for(std::chrono::seconds(10)) == std::future_status::timeout) {
    ADD_FAILURE() << "loading " << path << " blocked on the FIFO " << fifo;
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  }
  load.get();
}

// The valid triangle written to `path` with `levels` nested arrays as its `extras`.
void writeNested(const std::filesystem::path& path, std::size_t levels) {
  GltfFixture f = GltfFixture::triangle();
  f.doc["extras"] = "NEST";
  f.writeGltf(path);
  const std::vector<unsigned char> bytes = test::readAll(path);
  std::string text(bytes.begin(), bytes.end());
  text.replace(text.find("\"NEST\""), 6, std::string(levels, '[') + std::string(levels, ']'));
  test::writeText(path, text);
}

TEST(InputValidation, DeeplyNestedJsonIsRefusedBeforeTheParser) {
  // 100,000 nested arrays under extras overflowed the stack inside the JSON parser (SIGSEGV).
  TempDir dir;
  writeNested(dir / "deep.gltf", 100000);
  expectLoadError(dir / "deep.gltf", "deeper than 64 levels");
  // The limit itself loads: 64 levels in all (the document's object is the first).
  writeNested(dir / "deep_ok.gltf", 63);
  EXPECT_EQ(loadScene(dir / "deep_ok.gltf").triangleCount(), 1u);
  writeNested(dir / "deep_65.gltf", 64);
  expectLoadError(dir / "deep_65.gltf", "deeper than 64 levels");
}

TEST(InputValidation, BufferUriThatIsNotARegularFile) {
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.writeGltf(dir / "scene.gltf");
  nlohmann::json doc = nlohmann::json::parse(test::readAll(dir / "scene.gltf"));
  ASSERT_EQ(::mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
  std::filesystem::create_directory(dir / "folder.bin");
  std::filesystem::create_symlink("/dev/zero", dir / "zero.bin");
  const std::pair<const char*, const char*> cases[] = {
      {"fifo.bin", "FIFO"}, {"folder.bin", "directory"}, {"zero.bin", "device"}};
  for (const auto& [uri, reason] : cases) {
    doc["buffers"][0]["uri"] = uri;
    test::writeText(dir / "uri.gltf", doc.dump());
    expectLoadErrorWithoutBlocking(dir / "uri.gltf", reason, dir / "fifo.bin");
  }
}

TEST(InputValidation, MtllibThatIsNotARegularFile) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo.mtl").c_str(), 0600), 0);
  std::filesystem::create_directory(dir / "folder.mtl");
  for (const char* lib : {"fifo.mtl", "folder.mtl"}) {
    test::writeText(dir / "box.obj", std::string("mtllib ") + lib +
                                         "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1 2 3\n");
    expectLoadErrorWithoutBlocking(dir / "box.obj", lib, dir / "fifo.mtl");
  }
}

// A punctual light of the given glTF type and intensity at the triangle's node.
GltfFixture withLight(const char* type, double intensity) {
  GltfFixture f = GltfFixture::triangle();
  f.doc["extensions"] = {
      {"KHR_lights_punctual", {{"lights", {{{"type", type}, {"intensity", intensity}}}}}}};
  f.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  return f;
}

TEST(InputValidation, LightsAndEmissionBeyondTheRadiometricLimit) {
  // 1e40 cd = 1.5e37 W/sr is finite in float, but I/d² is not: Inf pixels, lights dropped.
  TempDir dir;
  withLight("point", 1e40).writeGltf(dir / "point.gltf");
  expectLoadError(dir / "point.gltf", "light intensity W/sr 1.46413e+37 exceeds bounce's limit");
  withLight("directional", 1e39).writeGltf(dir / "sun.gltf");
  expectLoadError(dir / "sun.gltf", "light irradiance W/m² 1.46413e+36 exceeds");
  GltfFixture emissive = GltfFixture::triangle();
  emissive.doc["meshes"][0]["primitives"][0]["material"] = 0;
  emissive.doc["materials"] = {
      {{"emissiveFactor", {1.0, 1.0, 1.0}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2e41}}}}}}};
  emissive.writeGltf(dir / "emission.gltf");
  expectLoadError(dir / "emission.gltf", "emitted radiance W/(sr·m²) 2.92826e+38 exceeds");
  // At the limit: 1e12 W/sr = 6.83e14 cd loads.
  withLight("point", 1e12 * 683.0).writeGltf(dir / "at_limit.gltf");
  EXPECT_FLOAT_EQ(loadScene(dir / "at_limit.gltf").lights.at(0).intensity.x, 1e12f);
}

TEST(InputValidation, CoordinatesBeyondTheLimit) {
  TempDir dir;
  const std::string limit = "beyond bounce's coordinate limit of 1e6 m";
  for (const float x : {1e20f, 3e38f, -3e38f}) {  // in the buffer
    GltfFixture f = GltfFixture::triangle();
    f.setFloat(4, x);  // vertex 1's x
    f.writeGltf(dir / "far.gltf");
    expectLoadError(dir / "far.gltf", "POSITION is " + limit);
  }
  GltfFixture scaled = GltfFixture::triangle();  // a root scale of 1e19
  scaled.doc["nodes"][0]["scale"] = {1e19, 1e19, 1e19};
  scaled.writeGltf(dir / "scaled.gltf");
  expectLoadError(dir / "scaled.gltf", "world coordinate " + limit);
  GltfFixture distant = GltfFixture::triangle();  // an emitter 5e9 m away
  distant.doc["nodes"][0]["translation"] = {0.0, 5e9, 0.0};
  distant.writeGltf(dir / "distant.gltf");
  expectLoadError(dir / "distant.gltf", "world coordinate " + limit);
  GltfFixture light = withLight("point", 1.0);
  light.doc["nodes"].push_back({{"translation", {2e6, 0.0, 0.0}},
                                {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  light.doc["nodes"][0].erase("extensions");
  light.doc["scenes"][0]["nodes"].push_back(1);
  light.writeGltf(dir / "light.gltf");
  expectLoadError(dir / "light.gltf", "light position is " + limit);
  // Just inside the limit loads.
  GltfFixture inside = GltfFixture::triangle();
  inside.doc["nodes"][0]["translation"] = {0.0, 0.0, 9.99e5};
  inside.writeGltf(dir / "inside.gltf");
  EXPECT_EQ(loadScene(dir / "inside.gltf").instances.size(), 1u);
}

TEST(InputValidation, CameraZnearBelowTheLimit) {
  // znear 1e-50 became 0 in float: a black frame and no message.
  TempDir dir;
  GltfFixture f = GltfFixture::triangle();
  f.doc["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 1e-50}}}}};
  f.doc["nodes"][0]["camera"] = 0;
  f.writeGltf(dir / "znear.gltf");
  expectLoadError(dir / "znear.gltf", "znear 1e-50 m is below bounce's limit of 1e-6 m");
}

// Each mutation of the valid triangle was loaded silently (a default taken, geometry dropped).
TEST(InputValidation, WrongJsonTypesAndValues) {
  TempDir dir;
  struct Case {
    const char* name;
    void (*mutate)(nlohmann::json&);
    const char* reason;
  };
  const Case cases[] = {
      {"negative byteOffset", [](nlohmann::json& d) { d["accessors"][0]["byteOffset"] = -4; },
       "accessors[0].byteOffset must be in 0.."},
      {"emissiveStrength string",
       [](nlohmann::json& d) {
         d["materials"] = {
             {{"emissiveFactor", {1, 1, 1}},
              {"extensions",
               {{"KHR_materials_emissive_strength", {{"emissiveStrength", "abc"}}}}}}};
         d["meshes"][0]["primitives"][0]["material"] = 0;
       },
       "emissiveStrength must be a number"},
      {"translation strings",
       [](nlohmann::json& d) {
         d["nodes"][0]["translation"] = {"1", "2", "3"};
       },
       "nodes[0].translation must be an array of 3 finite numbers"},
      {"translation of two",
       [](nlohmann::json& d) {
         d["nodes"][0]["translation"] = {1, 2};
       },
       "nodes[0].translation must be an array of 3 finite numbers"},
      {"mesh 0.5", [](nlohmann::json& d) { d["nodes"][0]["mesh"] = 0.5; },
       "nodes[0].mesh must be an integer"},
      {"primitives null", [](nlohmann::json& d) { d["meshes"][0]["primitives"] = nullptr; },
       "meshes[0].primitives must be a non-empty array"},
      {"extensionsRequired string",
       [](nlohmann::json& d) { d["extensionsRequired"] = "KHR_draco_mesh_compression"; },
       "extensionsRequired must be an array of strings"},
      {"asset.version 3.0", [](nlohmann::json& d) { d["asset"]["version"] = "3.0"; },
       "asset.version is \"3.0\"; bounce reads glTF 2.x"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    GltfFixture f = GltfFixture::triangle();
    c.mutate(f.doc);
    f.writeGltf(dir / "typed.gltf");
    expectLoadError(dir / "typed.gltf", c.reason);
    f.writeGlb(dir / "typed.glb");
    expectLoadError(dir / "typed.glb", c.reason);
  }
}

TEST(InputValidation, ObjNumbersThatAreNotFinite) {
  // tinyobjloader read "nan", "inf" and "1e999" as 0.
  TempDir dir;
  const std::string face = "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
  for (const char* v : {"v nan 1 0", "v inf 1 0", "v 0 1e999 0", "v 0 1", "v 2e6 0 0"}) {
    test::writeText(dir / "v.obj", std::string(v) + "\n" + face);
    expectLoadError(dir / "v.obj", "line 1:");
  }
  test::writeText(dir / "kd.mtl", "newmtl white\nKd nan 0.5 0.5\n");
  test::writeText(dir / "kd.obj", "mtllib kd.mtl\nv 0 1 0\n" + face);
  try {
    loadScene(dir / "kd.obj");
    ADD_FAILURE() << "Kd nan loaded";
  } catch (const LoadError& e) {
    EXPECT_NE(
        std::string(e.what()).find("kd.obj: material library 'kd.mtl': line 2: 'nan' in 'Kd'"),
        std::string::npos)
        << e.what();
  }
}

// The number check runs over parts of about 1 MiB in parallel (obj_load.cpp), each from a line
// after a "\n": a refused line is still named by its number in the whole file. 3 MiB of vertices
// whose lines end in "\n", "\r\n" and a lone "\r" in turn (each a line break to tinyobjloader);
// a bad number in the second MiB and another in the third: the first is named, then, alone, the
// second, and without either the file loads.
TEST(InputValidation, ObjNumberCheckNamesTheLineInALargeFile) {
  TempDir dir;
  const char* endings[] = {"\n", "\r\n", "\r"};
  const std::size_t lines = 200000;  // about 16 bytes each
  const std::size_t first = 90000, second = 170000;
  const auto write = [&](bool withFirst, bool withSecond) {
    std::string text;
    for (std::size_t k = 0; k < lines; ++k) {
      text += (withFirst && k == first)     ? "v nan 0.25 0.5"
              : (withSecond && k == second) ? "v 0.125 0.25 inf"
                                            : "v 0.125 0.25 0.5";
      text += endings[k % 3];
    }
    text += "f 1 2 3\n";
    ASSERT_GT(text.size(), std::size_t{3} << 20);
    test::writeText(dir / "big.obj", text);
  };
  write(true, true);
  expectLoadError(dir / "big.obj", "line " + std::to_string(first + 1) + ": 'nan' in 'v'");
  write(false, true);
  expectLoadError(dir / "big.obj", "line " + std::to_string(second + 1) + ": 'inf' in 'v'");
  write(false, false);
  EXPECT_NO_THROW(loadScene(dir / "big.obj"));
}

TEST(InputValidation, RandomBytesNamedObj) {
  // 64 KiB of random bytes rendered a black image with exit status 0.
  TempDir dir;
  std::mt19937 rng(9);
  std::vector<unsigned char> bytes(64 * 1024);
  for (unsigned char& b : bytes) b = static_cast<unsigned char>(rng());
  test::writeBytes(dir / "noise.obj", bytes);
  expectLoadError(dir / "noise.obj", "not a text file");
  test::writeText(dir / "empty.obj", "# nothing\nv 0 0 0\n");
  expectLoadError(dir / "empty.obj", "no faces");
}

TEST(InputValidation, TextureWiderThanTheGlMaximum) {
  // 17000×1 failed later in the renderer with GL_INVALID_VALUE, naming no file.
  TempDir dir;
  std::vector<unsigned char> row(17000 * 3, 128);
  ASSERT_NE(stbi_write_png((dir / "wide.png").c_str(), 17000, 1, 3, row.data(), 17000 * 3), 0);
  GltfFixture f = GltfFixture::triangle();
  f.doc["images"] = {{{"uri", "wide.png"}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  f.doc["meshes"][0]["primitives"][0]["material"] = 0;
  f.writeGltf(dir / "wide.gltf");
  expectLoadError(dir / "wide.gltf", "17000x1 texels exceeds bounce's texture limit");
  test::writeText(dir / "wide.mtl", "newmtl w\nKd 1 1 1\nmap_Kd wide.png\n");
  test::writeText(dir / "wide.obj",
                  "mtllib wide.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl w\nf 1 2 3\n");
  expectLoadError(dir / "wide.obj", "17000x1 texels exceeds bounce's texture limit");
  // The limit itself loads.
  std::vector<unsigned char> edge(static_cast<std::size_t>(kMaxTextureSide) * 3, 200);
  ASSERT_NE(stbi_write_png((dir / "edge.png").c_str(), kMaxTextureSide, 1, 3, edge.data(),
                           kMaxTextureSide * 3),
            0);
  f.doc["images"] = {{{"uri", "edge.png"}}};
  f.writeGltf(dir / "edge.gltf");
  EXPECT_EQ(loadScene(dir / "edge.gltf").textures.at(0).width, kMaxTextureSide);
}

}  // namespace
}  // namespace bounce
