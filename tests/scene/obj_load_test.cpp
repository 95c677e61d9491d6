// McGuire's OBJ Cornell boxes (shared scenes): counts, the Ke emitter, the Glossy variants'
// undefined material, and a cross-check against the project's own glTF box.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "scene/load.h"
#include "scene/loaders.h"
#include "scene/world_geometry.h"

namespace bounce {
namespace {

const std::string kMcGuire = BOUNCE_SHARED_SCENES "/mcguire_cornell_box/";

struct Extent {
  glm::vec3 lo{1e9f}, hi{-1e9f};
  double emitterArea = 0.0;
  glm::vec3 size() const { return hi - lo; }
};

Extent measure(const Scene& scene) {
  const WorldGeometry world = flatten(scene);
  Extent e;
  for (const glm::vec3& p : world.positions) {
    e.lo = glm::min(e.lo, p);
    e.hi = glm::max(e.hi, p);
  }
  for (std::size_t t = 0; t < world.triangleCount(); ++t) {
    if (scene.materials[world.triangleMaterial[t]].isEmissive()) {
      e.emitterArea += 0.5 * glm::length(world.triangleCross(t));
    }
  }
  return e;
}

TEST(McGuireCornellBox, OriginalLoadsWithItsLight) {
  const Scene scene = loadScene(kMcGuire + "CornellBox-Original.obj");
  // The file has 18 `f` lines, all quads: 36 triangles (loadScene then splits the floor where
  // the boxes stand on it, scene/crossing_cuts.h).
  EXPECT_EQ(loadSceneAsWritten(kMcGuire + "CornellBox-Original.obj").triangleCount(), 36u);
  EXPECT_GE(scene.triangleCount(), 36u);
  int emissive = 0;
  for (const Material& m : scene.materials) {
    if (!m.isEmissive()) continue;
    ++emissive;
    EXPECT_EQ(m.name, "light");
    EXPECT_EQ(m.emission, glm::vec3(17, 12, 4));  // Ke taken as W/(sr·m²), unconverted
  }
  EXPECT_EQ(emissive, 1);
  for (const Mesh& mesh : scene.meshes) EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
}

TEST(McGuireCornellBox, SameBoxAsOursUpToScale) {
  const Extent theirs = measure(loadScene(kMcGuire + "CornellBox-Original.obj"));
  const Extent ours = measure(loadScene(BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf"));
  // Two independent encodings of the same measured box, each with its own rounding
  // (McGuire's coordinates have 2 decimals on a ~2-unit box, ±0.5%): shape ratios agree to 2%.
  EXPECT_NEAR(theirs.size().y / theirs.size().x, ours.size().y / ours.size().x, 0.02);
  EXPECT_NEAR(theirs.size().z / theirs.size().x, ours.size().z / ours.size().x, 0.02);
  // The emitter's area relative to the floor's extent (width × depth): 130×105 mm over
  // 556×559.2 mm in ours; McGuire's light is 0.47×0.38 in a 2.02×2.03 box. His coordinates
  // are rounded to 0.01 (±0.005 on 0.38 and 0.47 is up to ±2.4% of the light's area), so
  // allow 5%.
  const double oursRatio = ours.emitterArea / (ours.size().x * ours.size().z);
  const double theirsRatio = theirs.emitterArea / (theirs.size().x * theirs.size().z);
  EXPECT_NEAR(theirsRatio / oursRatio, 1.0, 0.05);
}

TEST(McGuireCornellBox, GlossyVariantsReportTheUndefinedLightMaterial) {
  for (const char* name : {"CornellBox-Glossy.obj", "CornellBox-Glossy-Floor.obj"}) {
    try {
      loadScene(kMcGuire + name);
      FAIL() << name << " loaded although its material 'light' is undefined";
    } catch (const LoadError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(e.reason().find("'light'"), std::string::npos) << e.what();
      EXPECT_NE(e.reason().find("not defined"), std::string::npos) << e.what();
    }
  }
}

TEST(McGuireCornellBox, SphereVariantKeepsItsNormals) {
  const Scene scene = loadScene(kMcGuire + "CornellBox-Sphere.obj");
  EXPECT_GT(scene.triangleCount(), 36u);
  for (const Mesh& mesh : scene.meshes) {
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  }
}

// The conference room: all 331,179 triangles of the shared scene (its README) load, with
// finite unit normals. The load time is reported (not asserted) as the property load_seconds.
// As written: loadScene would go on to cut surfaces where others cross them (crossing_cuts.h),
// with a rule in metres that this file, in other units, does not meet (its wrapper
// content/conference/conference_panels.json scales it).
TEST(Conference, LoadsAllTriangles) {
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = loadSceneAsWritten(BOUNCE_SHARED_SCENES "/conference/conference.obj");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("load_seconds", std::to_string(seconds));
  std::printf("conference.obj: %zu triangles loaded in %.3f s\n", scene.triangleCount(), seconds);
  EXPECT_EQ(scene.triangleCount(), 331179u);
  for (const Material& m : scene.materials) EXPECT_FALSE(m.isEmissive()) << m.name;  // Ke is 0
  for (const Mesh& mesh : scene.meshes) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
  }
}

}  // namespace
}  // namespace bounce
