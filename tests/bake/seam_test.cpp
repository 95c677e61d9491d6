// Seams on a real atlas: a smooth cylinder (one mesh, shared vertices, smooth normals) that the
// atlas cuts into several charts. findSeams finds the cut edges and, after the bake's stitching,
// bilinear lookups on both sides of every seam agree.
#include <gtest/gtest.h>

#include <cmath>

#include "atlas/atlas.h"
#include "bake/lightmap_filters.h"
#include "bake_scenes.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

void addCylinder(Scene& scene, glm::vec3 base, float radius, float height, int segments,
                 uint32_t material) {
  Mesh mesh;
  mesh.name = "cylinder";
  for (int i = 0; i < segments; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    const glm::vec3 n(std::cos(a), 0.0f, std::sin(a));
    mesh.positions.push_back(base + radius * n);
    mesh.positions.push_back(base + radius * n + glm::vec3(0, height, 0));
    mesh.normals.push_back(n);
    mesh.normals.push_back(n);
  }
  for (int i = 0; i < segments; ++i) {
    const auto a = static_cast<uint32_t>(2 * i),
               b = static_cast<uint32_t>(2 * ((i + 1) % segments));
    // Outward-facing: counter-clockwise seen from outside.
    mesh.indices.insert(mesh.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
  }
  mesh.material = material;
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back(instance);
}

TEST(SeamStitching, CylinderChartsAgreeAcrossTheirSeamsAfterTheBake) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.7f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(10.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {1, 1, 1}, white);
  test::addQuad(world.scene, {0.1f, 0.95f, 0.1f}, {0.4f, 0.95f, 0.1f}, {0.4f, 0.95f, 0.4f},
                {0.1f, 0.95f, 0.4f}, lamp);
  addCylinder(world.scene, {0.6f, 0.0f, 0.6f}, 0.15f, 0.5f, 32, white);
  world.build();
  AtlasSettings atlasSettings;
  atlasSettings.texelBudget = 4096;
  const Atlas atlas = buildAtlas(world.scene, atlasSettings);
  const std::vector<Seam> seams = findSeams(world.scene, world.geometry, atlas.layout);
  ASSERT_GT(seams.size(), 0u) << "the cylinder should be cut into charts";

  LightmapBakeSettings settings = test::testBakeSettings(64);
  settings.stitch = false;
  const LightmapBake raw =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
  settings.stitch = true;
  const LightmapBake stitched =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
  // The scale: mean E over the cylinder's seam lookups.
  double scale = 0;
  for (const Seam& s : seams) scale += luminance(bilinear(raw.irradiance, 0.5f * (s.a0 + s.a1)));
  scale /= static_cast<double>(seams.size());
  ASSERT_GT(scale, 0.0);
  const double before = largestSeamJump(raw.irradiance, seams) / scale;
  const double after = largestSeamJump(stitched.irradiance, seams) / scale;
  EXPECT_GT(before, 0.05) << "64-spp noise alone makes the two sides differ";
  EXPECT_LT(after, 1e-2) << "before " << before;
  EXPECT_EQ(stitched.seams, seams.size());
}

}  // namespace
}  // namespace bounce
