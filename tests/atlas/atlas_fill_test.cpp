// How well the atlas fills: sub-texel pieces bundled (chart_bundle.h) and charts packed by their
// texel masks (chart_pack.h). Quantities are counted here from the scene and the layout.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "atlas/atlas.h"
#include "atlas_scenes.h"
#include "layout_checks.h"

namespace bounce::test {
namespace {

AtlasSettings atTexelSize(float metres) {
  AtlasSettings settings;
  settings.texelSize = metres;
  return settings;
}

// Adds a w × h rectangle at `origin` in the plane z = origin.z, facing +z or −z, as two
// triangles.
void addRectangle(Mesh& mesh, glm::vec3 origin, float w, float h, bool facingUp) {
  const auto base = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(),
                        {origin, origin + glm::vec3(w, 0, 0), origin + glm::vec3(w, h, 0),
                         origin + glm::vec3(0, h, 0)});
  if (facingUp)
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  else
    mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
}

uint32_t addMesh(Scene& scene, Mesh mesh) {
  if (scene.materials.empty()) scene.materials.push_back(Material{});
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
  scene.meshes.push_back(std::move(mesh));
  return static_cast<uint32_t>(scene.meshes.size() - 1);
}

std::set<uint32_t> chartsOf(const Atlas& atlas, std::size_t region, std::size_t first,
                            std::size_t count) {
  return {atlas.triangleChart[region].begin() + static_cast<std::ptrdiff_t>(first),
          atlas.triangleChart[region].begin() + static_cast<std::ptrdiff_t>(first + count)};
}

}  // namespace

// At 5 cm texels: 64 pieces of 8 × 4 mm facing up inside one 5 cm cube, 16 facing down in the
// same cube, 16 facing up in a cube 1 m away, and a 1 m square. Alone each piece would take one
// texel and 8 of padding (9 × 96 = 864 texels for 0.3 texel of surface); bundled, the three
// groups are three charts, and the square (wider than a texel) stays its own chart.
TEST(AtlasBundles, SubTexelPiecesCloseTogetherShareAChart) {
  Mesh mesh;
  mesh.name = "pieces";
  for (int k = 0; k < 64; ++k)
    addRectangle(mesh,
                 {0.002f + 0.011f * static_cast<float>(k % 4),
                  0.002f + 0.0055f * static_cast<float>(k / 4 % 8),
                  0.01f + 0.001f * static_cast<float>(k / 32)},
                 0.008f, 0.004f, true);
  for (int k = 0; k < 16; ++k)
    addRectangle(mesh,
                 {0.002f + 0.011f * static_cast<float>(k % 4),
                  0.002f + 0.011f * static_cast<float>(k / 4), 0.04f},
                 0.008f, 0.004f, false);
  for (int k = 0; k < 16; ++k)
    addRectangle(mesh,
                 {1.002f + 0.011f * static_cast<float>(k % 4),
                  0.002f + 0.011f * static_cast<float>(k / 4), 0.01f},
                 0.008f, 0.004f, true);
  addRectangle(mesh, {2.0f, 0.0f, 0.0f}, 1.0f, 1.0f, true);
  Scene scene;
  addInstance(scene, addMesh(scene, std::move(mesh)), glm::mat4(1));
  const Atlas atlas = buildAtlas(scene, atTexelSize(0.05f));
  EXPECT_EQ(regionProblem(scene, atlas), "");
  EXPECT_EQ(overlapProblem(atlas), "");  // pieces of a bundle never overlap either
  const std::set<uint32_t> up = chartsOf(atlas, 0, 0, 128);
  const std::set<uint32_t> down = chartsOf(atlas, 0, 128, 32);
  const std::set<uint32_t> far = chartsOf(atlas, 0, 160, 32);
  const std::set<uint32_t> square = chartsOf(atlas, 0, 192, 2);
  EXPECT_EQ(up.size(), 1u);
  EXPECT_EQ(down.size(), 1u);
  EXPECT_EQ(far.size(), 1u);
  EXPECT_EQ(square.size(), 1u);
  EXPECT_EQ(atlas.layout.chartCount, 4);
  EXPECT_EQ(atlas.chartKinds.bundle, 3);
  // Each piece keeps its shape and the texel density: texel area = world area / (5 cm)².
  const auto& uv = atlas.layout.instances[0].cornerUv;
  const glm::vec2 size(static_cast<float>(atlas.layout.width),
                       static_cast<float>(atlas.layout.height));
  for (std::size_t t = 0; t < 192; ++t) {
    const glm::vec2 a = uv[3 * t] * size, b = uv[3 * t + 1] * size, c = uv[3 * t + 2] * size;
    const float texels = 0.5f * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    EXPECT_NEAR(texels, 0.5f * 0.008f * 0.004f / (0.05f * 0.05f), 1e-4f) << "triangle " << t;
  }
}

}  // namespace bounce::test
