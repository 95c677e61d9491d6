// glTF extras.bounce.bake on a KHR_lights_punctual light: "all" marks it baked-only
// (Light::bakeDirect), "indirect" or nothing leaves it live; anything else is a LoadError.
#include <gtest/gtest.h>

#include "expect_load_error.h"
#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

test::GltfFixture pointLight(const nlohmann::json& extras) {
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  nlohmann::json light = {{"type", "point"}, {"intensity", 683.0}};
  if (!extras.is_null()) light["extras"] = extras;
  f.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {light}}}}};
  f.doc["nodes"].push_back(
      {{"name", "lamp"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  f.doc["scenes"][0]["nodes"] = {0, 1};
  return f;
}

TEST(GltfBakedLight, ExtrasBounceBakeMarksTheLight) {
  test::TempDir dir;
  const std::pair<nlohmann::json, bool> cases[] = {{nullptr, false},
                                                   {{{"bounce", {{"bake", "indirect"}}}}, false},
                                                   {{{"bounce", {{"bake", "all"}}}}, true},
                                                   {{{"other", 1}}, false}};
  for (const auto& [extras, baked] : cases) {
    pointLight(extras).writeGltf(dir / "light.gltf");
    EXPECT_EQ(loadScene(dir / "light.gltf").lights.at(0).bakeDirect, baked) << extras.dump();
  }
  pointLight({{"bounce", {{"bake", "sometimes"}}}}).writeGltf(dir / "bad.gltf");
  test::expectLoadError(dir / "bad.gltf", "extras.bounce.bake");
}

}  // namespace
}  // namespace bounce
