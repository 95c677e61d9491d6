// Mirroring node transforms keep a plane's front face towards the light: flatten() flips the
// winding of mirrored instances, and normals go through the inverse transpose.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "gltf_fixture.h"
#include "scene/load.h"
#include "scene/world_geometry.h"

namespace bounce {
namespace {

// content/point_over_plane: a plane at y = 0 facing +y, a point light 1 m above its centre.
TEST(MirroredInstance, PlaneStillFacesTheLight) {
  std::ifstream in(BOUNCE_SOURCE_DIR "/content/point_over_plane/point_over_plane.gltf");
  const nlohmann::json original = nlohmann::json::parse(in);
  test::TempDir dir;
  for (const nlohmann::json& scale :
       {nlohmann::json{-1.0, 1.0, 1.0}, nlohmann::json{1.0, 1.0, -1.0}}) {
    nlohmann::json doc = original;
    ASSERT_EQ(doc["nodes"][0]["name"], "plane");
    doc["nodes"][0]["scale"] = scale;
    test::writeText(dir / "mirrored.gltf", doc.dump());
    const Scene scene = loadScene(dir / "mirrored.gltf");
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].position, glm::vec3(0, 1, 0));
    const WorldGeometry world = flatten(scene);
    ASSERT_GT(world.triangleCount(), 0u);
    for (std::size_t t = 0; t < world.triangleCount(); ++t) {
      // (p1−p0)×(p2−p0) of a counter-clockwise (front) triangle points to its front side: up,
      // towards the light, with length twice the area (> 0).
      const glm::vec3 cross = world.triangleCross(t);
      EXPECT_GT(cross.y, 0.0f) << "scale " << scale.dump() << " triangle " << t;
      EXPECT_NEAR(cross.x, 0.0f, 1e-6f);
      EXPECT_NEAR(cross.z, 0.0f, 1e-6f);
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 n = world.normals[world.triangles[t][k]];
        EXPECT_LT(glm::distance(n, glm::vec3(0, 1, 0)), 1e-6f) << "scale " << scale.dump();
      }
    }
  }
}

}  // namespace
}  // namespace bounce
