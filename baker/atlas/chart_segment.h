// Chart segmentation: splits one instance's world-space triangles into charts by region growing
// over OpenMesh's half-edge structure. A chart grows from its largest unassigned triangle across
// shared edges while every triangle's normal stays within `coneHalfAngle` of the seed's normal
// and the fold across the edge is below `creaseAngle`. So a flat wall is one chart, a box is six,
// and a curved surface splits into charts no wider than the cone (each a height field over its
// seed plane, which the flattening needs). Then the fragments growth leaves between charts join
// a larger neighbour while the normals of both stay within `mergeHalfAngle` of one axis. No chart
// grows, merges or reports a contact across a cut edge (WorldMesh::cutEdges, where a wall
// crosses the surface: scene/crossing_cuts.h). So the components of faces joined across uncut
// edges are segmented apart, in parallel, and their charts numbered as one pass over all faces
// numbers them (by seed, in the order of decreasing area): the same charts at any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "atlas/chart.h"

namespace bounce {

struct SegmentSettings {
  float coneHalfAngle = 0.75f;    // radians (43°): widest normal spread inside one chart
  float creaseAngle = 0.61f;      // radians (35°): a sharper fold between two triangles splits
  float mergeHalfAngle = 1.05f;   // radians (60°): widest normal cone of two merged charts
  double degenerateArea = 1e-14;  // m²: triangles below it join no chart (see TriangleGroups)
};

// Two charts that share edges (in the half-edge structure), whatever the fold between them.
struct ChartContact {
  uint32_t a = 0, b = 0;  // indices into TriangleGroups::charts, a < b
  double length = 0.0;    // metres of shared edges
  double fold = 0.0;      // radians: the largest angle between the normals across those edges
};

struct TriangleGroups {
  std::vector<std::vector<uint32_t>> charts;  // triangle indices, each a connected region
  std::vector<uint32_t> degenerate;           // triangles with no area or no distinct corners
  std::vector<ChartContact> contacts;         // sorted by (a, b)
};

TriangleGroups segmentCharts(const WorldMesh& mesh, const SegmentSettings& settings);

// OpenMesh's error stream (a process-wide object) silenced while one is alive, counted across
// threads: segmentCharts refuses faces on purpose and holds one, and the atlas holds one around
// its parallel chart generation, so that no thread turns the stream back on while another's
// refusals are still being written. The stream is as it was once the last one ends.
class SilencedOpenMeshErrors {
 public:
  SilencedOpenMeshErrors();
  ~SilencedOpenMeshErrors();
  SilencedOpenMeshErrors(const SilencedOpenMeshErrors&) = delete;
  SilencedOpenMeshErrors& operator=(const SilencedOpenMeshErrors&) = delete;
};

}  // namespace bounce
