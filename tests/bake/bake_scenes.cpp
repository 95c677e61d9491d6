#include "bake_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace bounce::test {

bool QuadAtlas::texelCentre(int x, int y, glm::vec3& world, uint32_t& instance) const {
  const glm::vec2 t(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
  for (const QuadChart& c : charts) {
    const glm::vec2 local = t - c.origin;
    if (local.x < 0 || local.y < 0 || local.x > c.extent.x || local.y > c.extent.y) continue;
    world = c.corner + local.x * layout.texelSize * c.uAxis + local.y * layout.texelSize * c.vAxis;
    instance = c.instance;
    return true;
  }
  return false;
}

QuadAtlas quadAtlas(const Scene& scene, float texelSize, int width, int padding) {
  QuadAtlas atlas;
  atlas.layout.texelSize = texelSize;
  atlas.layout.padding = padding;
  atlas.layout.width = width;
  int x = padding, y = padding, shelf = 0;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
    const glm::vec3 p0 = glm::vec3(scene.instances[i].transform * glm::vec4(mesh.positions[0], 1));
    const glm::vec3 p1 = glm::vec3(scene.instances[i].transform * glm::vec4(mesh.positions[1], 1));
    const glm::vec3 p3 = glm::vec3(scene.instances[i].transform * glm::vec4(mesh.positions[3], 1));
    QuadChart chart;
    chart.instance = i;
    chart.corner = p0;
    chart.uAxis = glm::normalize(p1 - p0);
    chart.vAxis = glm::normalize(p3 - p0);
    chart.extent = glm::vec2(glm::length(p1 - p0), glm::length(p3 - p0)) / texelSize;
    const int w = static_cast<int>(std::ceil(chart.extent.x));
    const int h = static_cast<int>(std::ceil(chart.extent.y));
    if (x + w + padding > width) {
      x = padding;
      y += shelf + padding;
      shelf = 0;
    }
    chart.origin = glm::vec2(static_cast<float>(x), static_cast<float>(y));
    x += w + padding;
    shelf = std::max(shelf, h);
    atlas.charts.push_back(chart);
  }
  atlas.layout.height = y + shelf + padding;
  atlas.layout.chartCount = static_cast<int>(atlas.charts.size());
  const glm::vec2 size(static_cast<float>(atlas.layout.width),
                       static_cast<float>(atlas.layout.height));
  for (const QuadChart& c : atlas.charts) {
    const glm::vec2 corner[4] = {c.origin, c.origin + glm::vec2(c.extent.x, 0), c.origin + c.extent,
                                 c.origin + glm::vec2(0, c.extent.y)};
    InstanceLightmapUv region;
    region.instance = c.instance;
    for (const uint32_t index : scene.meshes[scene.instances[c.instance].mesh].indices)
      region.cornerUv.push_back(corner[index] / size);
    atlas.layout.instances.push_back(region);
  }
  return atlas;
}

void buildCornerLampRoom(World& world) {
  const uint32_t white = addMaterial(world.scene, glm::vec3(0.6f));
  const uint32_t lamp = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(50.0f));
  addInwardBox(world.scene, {0, 0, 0}, {1, 1, 1}, white);
  addQuad(world.scene, {0.05f, 0.95f, 0.05f}, {0.2f, 0.95f, 0.05f}, {0.2f, 0.95f, 0.2f},
          {0.05f, 0.95f, 0.2f}, lamp);
  // A floating horizontal board shading the far corner's floor (double-sided white).
  const uint32_t board = addMaterial(world.scene, glm::vec3(0.6f), glm::vec3(0.0f), true);
  addQuad(world.scene, {0.5f, 0.3f, 0.5f}, {0.5f, 0.3f, 0.95f}, {0.95f, 0.3f, 0.95f},
          {0.95f, 0.3f, 0.5f}, board);
  world.build();
}

LightmapBakeSettings testBakeSettings(int spp, uint32_t seed, int threads) {
  LightmapBakeSettings settings;
  settings.irradiance.maxSpp = spp;
  settings.irradiance.seed = seed;
  settings.irradiance.threads = threads;
  settings.leak.threads = threads;
  return settings;
}

void expectSameLightmap(const LightmapBake& a, const LightmapBake& b) {
  ASSERT_EQ(a.irradiance.pixels.size(), b.irradiance.pixels.size());
  EXPECT_EQ(0, std::memcmp(a.irradiance.pixels.data(), b.irradiance.pixels.data(),
                           a.irradiance.pixels.size() * sizeof(glm::vec3)));
  EXPECT_EQ(a.samples, b.samples);
}

}  // namespace bounce::test
