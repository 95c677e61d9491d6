// Chart flattening: lays one chart's world-space triangles flat in texel units at one texel
// density (texelSize metres per texel edge), then turns it to its smallest bounding rectangle.
//   near-planar charts (every normal within planarAngle of the mean): orthogonal projection onto
//   the mean plane, so UV area / world area = 1/texelSize² on every triangle (exactly when flat);
//   curved charts: least-squares conformal map (Lévy et al. 2002; angles kept, areas stretched
//   as little as a conformal map allows), scaled so the chart's UV area / world area is
//   1/texelSize² on the whole.
// A flattening with a flipped or overlapping triangle is rejected (empty result).
#pragma once

#include <cstdint>
#include <vector>

#include "atlas/chart.h"

namespace bounce {

struct FlatChart {
  std::vector<glm::vec2> cornerUv;  // 3 per chart triangle, texel units; empty when rejected
  ChartSource source = ChartSource::Planar;
};

inline constexpr float kPlanarAngle = 0.0873f;  // radians (5°): cos 5° = 0.996 area kept

FlatChart flattenPlanar(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                        float texelSize);
FlatChart flattenConformal(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                           float texelSize);
// The same with the chart's connectivity given: cornerVertex[3k + j] is the chart vertex (ids in
// [0, n), every id used) of corner j of triangles[k]; corners at one position with different ids
// are a seam, laid out apart. Ids must join only corners at one position.
FlatChart flattenConformal(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                           const std::vector<int>& cornerVertex, float texelSize);
// Planar when near-planar, else conformal, else planar again if the conformal map failed;
// empty when every attempt has a flipped or overlapping triangle.
FlatChart flattenChart(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                       float texelSize);

// Rotates the chart to its minimum-area bounding rectangle (over its convex hull's edges), then
// by 90° if it is taller than wide, and moves its lower corner to (0, 0).
void orientChart(std::vector<glm::vec2>& cornerUv);

}  // namespace bounce
