// The project's Cornell box (content/cornell_box/cornell_box.gltf) against the numbers of
// Cornell's data page (content/README.md): geometry in metres, reflectances, the emitter's
// radiance after the photometric round trip, and the standard camera.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/load.h"
#include "scene/world_geometry.h"

namespace bounce {
namespace {

const char* kCornell = BOUNCE_SOURCE_DIR "/content/cornell_box/cornell_box.gltf";

const Material& materialNamed(const Scene& scene, const std::string& name) {
  for (const Material& m : scene.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

TEST(CornellBox, LoadsTrianglesAndMaterials) {
  const Scene scene = loadScene(kCornell);
  // 5 room quads + the light quad + 5 visible faces per block: (5 + 1 + 10) quads × 2.
  EXPECT_EQ(scene.triangleCount(), 32u);
  EXPECT_EQ(scene.materials.size(), 4u);
  EXPECT_EQ(materialNamed(scene, "white").albedo, glm::vec3(0.725f, 0.71f, 0.68f));
  EXPECT_EQ(materialNamed(scene, "red").albedo, glm::vec3(0.63f, 0.065f, 0.05f));
  EXPECT_EQ(materialNamed(scene, "green").albedo, glm::vec3(0.14f, 0.45f, 0.091f));
  for (const Material& m : scene.materials) EXPECT_EQ(m.isEmissive(), m.name == "light");
}

TEST(CornellBox, EmitterRadianceIs17_12_4AfterPhotometricConversion) {
  const Scene scene = loadScene(kCornell);
  const Material& light = materialNamed(scene, "light");
  // Stored as emissiveFactor (1, 12/17, 4/17) × 17·683 nits; the double-precision conversion
  // must give the float nearest to the intended radiance.
  EXPECT_FLOAT_EQ(light.emission.r, 17.0f);
  EXPECT_FLOAT_EQ(light.emission.g, 12.0f);
  EXPECT_FLOAT_EQ(light.emission.b, 4.0f);
}

TEST(CornellBox, GeometryInMetresFacingTheInterior) {
  const Scene scene = loadScene(kCornell);
  const WorldGeometry world = flatten(scene);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& p : world.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Data page extremes: x 0…556.0 mm, y 0…548.8 mm, z 0…559.2 mm.
  EXPECT_NEAR(lo.x, 0.0f, 1e-6f);
  EXPECT_NEAR(hi.x, 0.556f, 1e-6f);
  EXPECT_NEAR(hi.y, 0.5488f, 1e-6f);
  EXPECT_NEAR(hi.z, 0.5592f, 1e-6f);
  const glm::vec3 centre(0.278f, 0.2744f, 0.2796f);
  double emitterArea = 0.0;
  for (std::size_t t = 0; t < world.triangleCount(); ++t) {
    const glm::vec3 n = world.triangleCross(t);
    const glm::uvec3 tri = world.triangles[t];
    const glm::vec3 c =
        (world.positions[tri.x] + world.positions[tri.y] + world.positions[tri.z]) / 3.0f;
    const std::string& instance = scene.instances[world.triangleInstance[t]].name;
    if (instance == "light") {
      emitterArea += 0.5 * glm::length(n);
      EXPECT_GT(-n.y, 0.999f * glm::length(n)) << "the light faces down";
      EXPECT_NEAR(c.y, 0.5487f, 1e-6f) << "0.1 mm below the ceiling";
    } else if (instance.find("block") == std::string::npos) {
      EXPECT_GT(glm::dot(n, centre - c), 0.0f) << instance << " faces the interior";
    }
    // Shading normals agree with the winding (flat quads).
    EXPECT_GT(glm::dot(world.normals[tri.x], n), 0.99f * glm::length(n)) << instance;
  }
  EXPECT_NEAR(emitterArea, 0.130 * 0.105, 1e-7);  // 130 mm × 105 mm
}

TEST(CornellBox, StandardCamera) {
  const Scene scene = loadScene(kCornell);
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& camera = scene.cameras[0];
  EXPECT_NEAR(camera.yfov, 2.0 * std::atan(12.5 / 35.0), 1e-6);  // 25 mm film, 35 mm lens
  EXPECT_FLOAT_EQ(camera.aspect, 1.0f);
  EXPECT_NEAR(glm::distance(camera.position(), glm::vec3(0.278f, 0.273f, -0.8f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(camera.forward(), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(camera.up(), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  // The red wall (x ≈ 0.55 m) is on the image's left: against the camera's right vector.
  const glm::vec3 right = glm::cross(camera.forward(), camera.up());
  EXPECT_LT(glm::dot(glm::vec3(0.554f, 0.27f, 0.28f) - camera.position(), right), 0.0f);
}

TEST(PointOverPlane, LightCameraAndPlane) {
  const Scene scene =
      loadScene(BOUNCE_SOURCE_DIR "/content/point_over_plane/point_over_plane.gltf");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_FLOAT_EQ(scene.lights[0].intensity.r, 1.0f);  // 683 cd
  EXPECT_EQ(scene.lights[0].position, glm::vec3(0, 1, 0));
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_NEAR(glm::distance(scene.cameras[0].forward(), glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(scene.triangleCount(), 2u);
  EXPECT_FLOAT_EQ(scene.materials.at(0).albedo.g, 0.5f);
}

}  // namespace
}  // namespace bounce
