// Where each static instance's triangles lie in the lightmap atlas. GL-free; written by the
// atlas (baker/atlas), stored in the bake folder, read by the renderer.
//
// Atlas coordinates: (u, v) in [0,1]², u from the left column to the right, v from the top row
// to the bottom row (the Image convention: rows top first). Texel (x, y) of a W×H atlas covers
// [x/W, (x+1)/W] × [y/H, (y+1)/H]; its centre is ((x+0.5)/W, (y+0.5)/H).
//
// UVs are per triangle corner, not per vertex: a mesh vertex shared by two charts has two
// atlas positions, so no mesh is ever split or re-indexed for the lightmap. Each static instance
// has its own region (two instances of one mesh at different scales get different texel
// counts); dynamic instances have none.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

struct InstanceLightmapUv {
  uint32_t instance = 0;            // index into Scene::instances (a static instance)
  std::vector<glm::vec2> cornerUv;  // 3 per triangle, in the order of its mesh's `indices`
};

struct LightmapLayout {
  int width = 0;                              // texels
  int height = 0;                             // texels
  float texelSize = 0.0f;                     // metres: edge of one texel on the surface
  int padding = 2;                            // texels kept free around every chart
  int chartCount = 0;                         // charts packed
  float utilisation = 0.0f;                   // covered texels / (width × height)
  std::vector<InstanceLightmapUv> instances;  // sorted by instance index

  // The region of `instance`, or nullptr when it has none (dynamic, or no triangles).
  const InstanceLightmapUv* find(uint32_t instance) const;
};

}  // namespace bounce
