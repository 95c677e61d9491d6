// A lightmapped floor under VPLs with a dynamic quad over it: the scene of the cost view's VPL
// counts (cost_view_test.cpp) and of the vertex gather's frame cache (frame_cache_test.cpp).
#pragma once

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "lightmap_scenes.h"
#include "test_scenes.h"

namespace bounce::test {

// A 1 m lightmapped static floor (atlas u = x + ½, v = z + ½) and a 0.2 m dynamic quad 0.5 m
// over its centre, in `cells` × `cells` squares, seen from 1 m above; VPLs on a wall at
// x = −0.45 and over the floor.
struct VplCostScene {
  Scene scene;
  Camera camera = downCamera(1.0f);
  Bake bake;
};

inline VplCostScene vplCostScene(int cells = 1) {
  VplCostScene s;
  Material floor;
  floor.name = "floor";
  floor.albedo = glm::vec3(0.5f);
  addQuad(s.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  Material hover;
  hover.name = "hover";
  hover.albedo = glm::vec3(0.7f);
  const float step = 0.2f / static_cast<float>(cells);
  Mesh grid;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      grid.positions.emplace_back(-0.1f + step * static_cast<float>(i), 0.5f,
                                  0.1f - step * static_cast<float>(j));
      grid.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  // Vertices in a shuffled order, so that a corner reading another vertex's light reads one
  // far from it.
  std::vector<uint32_t> slot(grid.positions.size());
  std::iota(slot.begin(), slot.end(), 0u);
  std::shuffle(slot.begin(), slot.end(), std::mt19937(11));
  Mesh shuffled = grid;
  for (std::size_t k = 0; k < slot.size(); ++k) shuffled.positions[slot[k]] = grid.positions[k];
  grid.positions = shuffled.positions;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const auto at = [&](int di, int dj) {
        return slot[static_cast<std::size_t>((j + dj) * (cells + 1) + i + di)];
      };
      grid.indices.insert(grid.indices.end(),
                          {at(0, 0), at(1, 0), at(1, 1), at(0, 0), at(1, 1), at(0, 1)});
    }
  addMesh(s.scene, std::move(grid), hover);
  s.scene.instances[1].mobility = Mobility::Dynamic;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vpl> vpls;
  for (int i = 0; i < 400; ++i) {
    Vpl v;
    const bool wall = i % 2 == 0;
    v.position = wall ? glm::vec3(-0.45f, 0.6f * u(rng), -0.45f + 0.9f * u(rng))
                      : glm::vec3(-0.45f + 0.9f * u(rng), 0.0f, -0.45f + 0.9f * u(rng));
    v.normal = wall ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    v.flux = glm::vec3(1e-3f);
    vpls.push_back(v);
  }
  Bake& bake = s.bake;
  bake.layout.width = bake.layout.height = 8;
  bake.layout.texelSize = 1.0f / 8.0f;
  bake.layout.instances = {unitFloorRegion(s.scene)};
  bake.irradiance = Image(8, 8, glm::vec3(1.0f));
  bake.manifest = minimalManifest(s.scene);
  bake.manifest.vpls = BakeManifest::Vpls{.count = vpls.size(), .clampDistance = 0.05f};
  bake.vpls = vpls;
  return s;
}

}  // namespace bounce::test
