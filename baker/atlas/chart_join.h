// The connectivity of two charts' union for one conformal map, joined along one smooth run of
// their shared boundary. Two charts may share more than one run of edges: the front and back of a
// thin double-sided plate share their whole rim, two halves of a tube share both long sides.
// Joined everywhere they would close into a sphere or a tube, which no map lays flat without
// folding; joined along the longest run only (a chain of shared boundary edges turning less than
// 45° at each vertex) the union is a disc again (two discs glued along one path), opened like a
// book at the other runs, which become a seam inside the chart. Internal to the atlas.
#pragma once

#include <cstdint>
#include <vector>

#include "atlas/chart.h"

namespace bounce {

struct JoinedCharts {
  std::vector<uint32_t> triangles;  // a's then b's
  std::vector<int> cornerVertex;    // 3 per triangle: chart vertex ids in [0, n), all used
  bool everyEdge = false;           // the run holds every shared edge: welded by position alike
};

// The union joined along each of the `most` longest runs, longest first (nothing when the charts
// share no boundary edge). `aUv`, `bUv`: each chart's own flattening (3 corners per triangle):
// corners at one position and one UV are one vertex of that chart, so seams earlier joins left
// open stay open.
std::vector<JoinedCharts> joinAlongRuns(const WorldMesh& mesh, const std::vector<uint32_t>& a,
                                        const std::vector<glm::vec2>& aUv,
                                        const std::vector<uint32_t>& b,
                                        const std::vector<glm::vec2>& bUv, std::size_t most);

}  // namespace bounce
