// The .json scene wrapper: a model referenced by path, scaled into metres, with lights and a
// camera added; malformed wrappers are LoadErrors naming the wrapper.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "scene/framing.h"
#include "scene/load.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

fs::path writeWrapper(const std::string& name, const std::string& text) {
  const fs::path dir =
      fs::temp_directory_path() / ("bounce_scene_json_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

const std::string kCornell = BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf";

TEST(SceneJson, ScalesTheModelAndAddsLightsAndCamera) {
  const Scene original = loadScene(kCornell);
  const fs::path path = writeWrapper("half.json", R"({
    "model": ")" + kCornell + R"(", "scale": 0.5,
    "lights": [{"type": "spot", "position": [0.1, 0.2, 0.3], "direction": [0, -2, 0],
                "intensity": [1, 2, 3], "inner_cone": 0.2, "outer_cone": 0.4}],
    "camera": {"name": "c", "position": [0, 0.1, 1], "target": [0, 0.1, 0], "yfov": 0.5}})");
  const Scene scene = loadScene(path);
  const Bounds a = sceneBounds(original), b = sceneBounds(scene);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(b.lo[axis], 0.5f * a.lo[axis], 1e-6f);
    EXPECT_NEAR(b.hi[axis], 0.5f * a.hi[axis], 1e-6f);
  }
  // Radiometry is untouched by the scale: emission is radiance.
  ASSERT_EQ(scene.materials.size(), original.materials.size());
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    EXPECT_EQ(scene.materials[m].emission, original.materials[m].emission);
  ASSERT_EQ(scene.lights.size(), original.lights.size() + 1);
  const Light& spot = scene.lights.back();
  EXPECT_EQ(spot.type, LightType::Spot);
  EXPECT_EQ(spot.position, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(spot.direction, glm::vec3(0, -1, 0));
  EXPECT_EQ(spot.intensity, glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.4f);
  ASSERT_EQ(scene.cameras.size(), original.cameras.size() + 1);
  EXPECT_EQ(scene.cameras.front().name, "c");
  EXPECT_NEAR(scene.cameras.front().position().z, 1.0f, 1e-6f);
  EXPECT_NEAR(scene.cameras.front().forward().z, -1.0f, 1e-6f);
  // The model's own camera moved with the model.
  EXPECT_NEAR(scene.cameras[1].position().z, 0.5f * original.cameras[0].position().z, 1e-5f);
}

// An "emitters" entry is one static instance of one mesh holding all its quads (front u × v),
// with its own emissive material; coordinates are metres, not scaled by the wrapper.
TEST(SceneJson, EmittersAddOneMeshOfQuadsEach) {
  const Scene original = loadScene(kCornell);
  const fs::path path = writeWrapper("panels.json", R"({
    "model": ")" + kCornell + R"(", "scale": 0.5,
    "emitters": [{"name": "panels", "radiance": [3, 2, 1], "albedo": [0.1, 0.2, 0.3], "bake": "all",
                  "quads": [{"corner": [0, 1, 0], "u": [0.5, 0, 0], "v": [0, 0, 0.25]},
                            {"corner": [2, 1, 0], "u": [0.5, 0, 0], "v": [0, 0, 0.25]}]}]})");
  const Scene scene = loadScene(path);
  ASSERT_EQ(scene.instances.size(), original.instances.size() + 1);
  const Instance& added = scene.instances.back();
  EXPECT_EQ(added.name, "panels");
  EXPECT_EQ(added.mobility, Mobility::Static);
  EXPECT_EQ(added.transform, glm::mat4(1.0f));
  const Mesh& mesh = scene.meshes.at(added.mesh);
  ASSERT_EQ(mesh.triangleCount(), 4u);
  EXPECT_EQ(mesh.positions[5], glm::vec3(2.5f, 1.0f, 0.0f));  // metres as written
  EXPECT_EQ(mesh.normals[0], glm::vec3(0, -1, 0));            // (x × z) = −y
  const Material& m = scene.materials.at(mesh.material);
  EXPECT_EQ(m.emission, glm::vec3(3, 2, 1));
  EXPECT_EQ(m.albedo, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_FALSE(m.doubleSided);
  EXPECT_TRUE(m.bakeDirect);
}

TEST(SceneJson, MalformedWrappersNameTheWrapper) {
  const std::pair<std::string, std::string> cases[] = {
      {"{}", "needs \"model\""},
      {R"({"model": "missing.obj"})", "file not found"},
      {R"({"model": ")" + kCornell + R"(", "scale": -1})", "'scale' must be positive"},
      {R"({"model": ")" + kCornell + R"(", "lights": [{"type": "area"}]})", "unknown light type"},
      {"{not json", "invalid JSON"},
      // The model's loader checked its own limits; the wrapper's scale and lights are checked
      // against the same ones (docs/input_limits.md).
      {R"({"model": ")" + kCornell + R"(", "scale": 1e30})", "vertex beyond"},
      {R"({"model": ")" + kCornell + R"(", "lights": [{"type": "point",
          "position": [0, 1, 0], "intensity": [1e20, 1, 1]}]})",
       "beyond"},
      {R"({"model": ")" + kCornell + R"(", "lights": [{"type": "point",
          "position": [0, 1e30, 0], "intensity": [1, 1, 1]}]})",
       "placed beyond"},
      {R"({"model": ")" + kCornell + R"(", "camera": {"position": [0, 0.1, 1],
          "target": [0, 0.1, 0], "znear": 1e-30}})",
       "znear below"},
      {std::string(100000, '[') + std::string(100000, ']'), "nest"},
      {R"({"model": ")" + kCornell + R"(", "emitters": [{"radiance": [1, 1, 1]}]})",
       "needs \"quads\""},
      {R"({"model": ")" + kCornell + R"(", "emitters": [{"radiance": [1, 1, 1],
          "quads": [{"corner": [0, 1, 0], "u": [1, 0, 0], "v": [2, 0, 0]}]}]})",
       "quad of zero area"},
      {R"({"model": ")" + kCornell + R"(", "emitters": [{"radiance": [-1, 1, 1],
          "quads": [{"corner": [0, 1, 0], "u": [1, 0, 0], "v": [0, 0, 1]}]}]})",
       "negative radiance"},
      {R"({"model": ")" + kCornell + R"(", "emitters": [{"radiance": [1, 1, 1], "bake": "some",
          "quads": [{"corner": [0, 1, 0], "u": [1, 0, 0], "v": [0, 0, 1]}]}]})",
       "'bake' must be"},
  };
  int i = 0;
  for (const auto& [text, reason] : cases) {
    const fs::path path = writeWrapper("bad" + std::to_string(i++) + ".json", text);
    try {
      loadScene(path);
      ADD_FAILURE() << "no error for " << text;
    } catch (const LoadError& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace bounce
