// Which surface each lightmap texel covers, as sample points on the world's triangles.
//
// A texel (x, y) covers [x, x+1] × [y, y+1] in texel space (atlas UV × (width, height), see
// engine/bake_folder/lightmap_layout.h). Its part of every triangle whose atlas image overlaps it
// is found exactly by clipping the triangle against the texel square (atlas/uv_geometry.h
// clipTriangleToBox, Sutherland–Hodgman, the same rule the atlas reports coverage by), so a
// texel touched by any sliver of a triangle is covered (conservative coverage: chart edges are
// never missed) and a texel straddling several triangles gets each triangle's part. Candidate
// sample points are drawn uniformly by area over those clipped polygons (a scrambled Sobol
// pattern per texel), mapped to world position and interpolated shading normal through the
// triangle's barycentrics.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/lightmap_layout.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"

namespace bounce {

struct TexelPoint {
  glm::vec3 position{0.0f};         // world, metres
  glm::vec3 shadingNormal{0.0f};    // unit, interpolated from the vertex normals (front side)
  glm::vec3 geometricNormal{0.0f};  // unit, the triangle's front face
  glm::vec2 texelPosition{0.0f};    // texel space, where the point lies in the atlas
  uint32_t triangle = 0;            // index into WorldGeometry::triangles
};

struct TexelCoverage {
  int width = 0;
  int height = 0;
  // Points of texel i are points[first[i] .. first[i+1]); a texel with none is not covered.
  std::vector<uint32_t> first;  // width × height + 1
  std::vector<TexelPoint> points;
  std::vector<float> coveredArea;  // per texel: area of its clipped polygons, texel² (≤ 1 each)

  std::size_t texelCount() const { return static_cast<std::size_t>(width) * height; }
  uint32_t pointCount(std::size_t texel) const { return first[texel + 1] - first[texel]; }
  bool covered(std::size_t texel) const { return pointCount(texel) > 0; }
};

// First world triangle and vertex of every instance in flatten()'s order (WorldGeometry holds
// the instances' triangles and vertices one after another).
struct InstanceBase {
  uint32_t triangle = 0;
  uint32_t vertex = 0;
};
std::vector<InstanceBase> instanceBases(const Scene& scene);

// `pointsPerTexel` candidate points per covered texel, from the Sobol pattern (seed, texel).
// geometry = flatten(scene); the layout's corner UVs follow each mesh's `indices`.
TexelCoverage buildTexelCoverage(const Scene& scene, const WorldGeometry& geometry,
                                 const LightmapLayout& layout, int pointsPerTexel, uint32_t seed);

}  // namespace bounce
