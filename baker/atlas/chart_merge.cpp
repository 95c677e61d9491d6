#include "atlas/chart_merge.h"

#include <algorithm>
#include <map>

#include "atlas/uv_geometry.h"

namespace bounce {
namespace {

// Every triangle's UV area / world area within [1/3, 3] of the chart's (which is 1 in metres).
bool areaScalesBounded(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                       const std::vector<glm::vec2>& uv) {
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const double world = mesh.area(triangles[k]);
    const double flat =
        std::abs(static_cast<double>(signedArea(uv[3 * k], uv[3 * k + 1], uv[3 * k + 2])));
    if (flat < world / 3.0 || flat > 3.0 * world) return false;
  }
  return true;
}

}  // namespace

std::vector<FlatGroup> mergeSmallCharts(const WorldMesh& mesh, std::vector<FlatGroup> groups,
                                        const std::vector<ChartContact>& contacts,
                                        double smallArea) {
  const std::size_t n = groups.size();
  std::vector<double> area(n, 0.0);
  for (std::size_t c = 0; c < n; ++c)
    for (const uint32_t t : groups[c].triangles) area[c] += mesh.area(t);
  std::vector<std::map<uint32_t, double>> touching(n);  // chart → neighbour → shared length
  for (const ChartContact& contact : contacts) {
    touching[contact.a][contact.b] += contact.length;
    touching[contact.b][contact.a] += contact.length;
  }
  std::vector<bool> alive(n, true);
  std::vector<uint32_t> order(n);
  for (std::size_t c = 0; c < n; ++c) order[c] = static_cast<uint32_t>(c);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return area[a] < area[b]; });
  for (const uint32_t c : order) {
    if (!alive[c] || area[c] >= smallArea || groups[c].flat.cornerUv.empty()) continue;
    std::vector<std::pair<double, uint32_t>> candidates;  // (−shared length, neighbour)
    for (const auto& [d, length] : touching[c])
      if (alive[d] && !groups[d].flat.cornerUv.empty() && area[d] < 8.0 * smallArea)
        candidates.emplace_back(-length, d);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [negativeLength, d] : candidates) {
      std::vector<uint32_t> triangles = groups[d].triangles;
      triangles.insert(triangles.end(), groups[c].triangles.begin(), groups[c].triangles.end());
      FlatChart flat = flattenConformal(mesh, triangles, 1.0f);
      if (flat.cornerUv.empty() || !areaScalesBounded(mesh, triangles, flat.cornerUv)) continue;
      groups[d] = {std::move(triangles), std::move(flat)};
      area[d] += area[c];
      alive[c] = false;
      for (const auto& [e, length] : touching[c]) {
        if (e == d) continue;
        touching[e].erase(c);
        touching[e][d] += length;
        touching[d][e] += length;
      }
      touching[d].erase(c);
      break;
    }
  }
  std::vector<FlatGroup> kept;
  for (std::size_t c = 0; c < n; ++c)
    if (alive[c]) kept.push_back(std::move(groups[c]));
  return kept;
}

}  // namespace bounce
