// Systematic corruption of a valid scene file: every truncation and many single-byte edits.
// Whatever the damage, loading either succeeds or throws LoadError (naming the file); any other
// exception or a crash fails the test. The files come from the one-triangle fixture, so each
// case is small and the whole sweep takes well under a second.
#include <gtest/gtest.h>

#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

// Loads; returns true when it loaded, false on LoadError; anything else propagates to gtest.
bool loadsOrLoadError(const std::filesystem::path& path) {
  try {
    loadScene(path);
    return true;
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << e.what();
    return false;
  }
}

// Writes `bytes` to a fresh file (a new name each time: rewriting one file in place makes ext4
// flush it on every close, 100× slower), loads it, removes it.
bool loadsOrLoadError(const test::TempDir& dir, const std::string& ext,
                      const std::vector<unsigned char>& bytes) {
  static int counter = 0;
  const std::filesystem::path path = dir / ("case" + std::to_string(counter++) + ext);
  test::writeBytes(path, bytes);
  const bool loaded = loadsOrLoadError(path);
  std::filesystem::remove(path);
  return loaded;
}

test::GltfFixture fixtureWithEverything() {
  test::GltfFixture f = test::GltfFixture::triangle();
  const int normals = f.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
  const int uv = f.addFloats({0, 0, 1, 0, 0, 1}, "VEC2");
  f.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = normals;
  f.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
  f.doc["meshes"][0]["primitives"][0]["material"] = 0;
  f.doc["materials"] = {{{"emissiveFactor", {1, 1, 1}}}};
  f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"intensity", 10}, {"spot", {{"outerConeAngle", 0.5}}}}};
  f.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  f.doc["nodes"][0]["children"] = {1};
  f.doc["nodes"].push_back(
      {{"camera", 0}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  return f;
}

TEST(Mutation, EveryTruncationOfAGlb) {
  test::TempDir dir;
  fixtureWithEverything().writeGlb(dir / "whole.glb");
  const std::vector<unsigned char> whole = test::readAll(dir / "whole.glb");
  ASSERT_NO_THROW(loadScene(dir / "whole.glb"));
  for (std::size_t keep = 0; keep < whole.size(); ++keep) {
    EXPECT_FALSE(
        loadsOrLoadError(dir, ".glb", {whole.begin(), whole.begin() + static_cast<long>(keep)}))
        << "truncated to " << keep << " bytes";
  }
}

TEST(Mutation, SingleByteEditsOfAGlb) {
  test::TempDir dir;
  fixtureWithEverything().writeGlb(dir / "whole.glb");
  const std::vector<unsigned char> whole = test::readAll(dir / "whole.glb");
  for (std::size_t i = 0; i < whole.size(); ++i) {
    for (const unsigned char value : {0x00, 0xff, 0x39 /* '9' */, 0x2d /* '-' */}) {
      std::vector<unsigned char> edited = whole;
      edited[i] = value;
      loadsOrLoadError(dir, ".glb", edited);  // either outcome is fine; no crash, no other error
    }
  }
}

TEST(Mutation, NumberEditsOfAGltf) {
  // Every digit of the JSON replaced by '9' or '-' : large and negative indices, counts,
  // offsets and strides, each in its own file.
  test::TempDir dir;
  const test::GltfFixture f = fixtureWithEverything();
  f.writeGltf(dir / "whole.gltf");
  const std::vector<unsigned char> json = test::readAll(dir / "whole.gltf");
  int errors = 0;
  for (std::size_t i = 0; i < json.size(); ++i) {
    if (json[i] < '0' || json[i] > '9') continue;
    for (const unsigned char value : {'9', '-'}) {
      std::vector<unsigned char> edited = json;
      edited[i] = value;
      errors += loadsOrLoadError(dir, ".gltf", edited) ? 0 : 1;  // still refers to whole.bin
    }
  }
  EXPECT_GT(errors, 0);  // the sweep did reach the validation
}

}  // namespace
}  // namespace bounce
