#include "atlas/chart_merge.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "atlas/chart_join.h"
#include "atlas/uv_geometry.h"

namespace bounce {
namespace {

// Every triangle's UV area / world area within [1/bound, bound] of the chart's (1 in metres).
bool areaScalesBounded(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                       const std::vector<glm::vec2>& uv, double bound) {
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const double world = mesh.area(triangles[k]);
    const double flat =
        std::abs(static_cast<double>(signedArea(uv[3 * k], uv[3 * k + 1], uv[3 * k + 2])));
    if (flat < world / bound || flat > bound * world) return false;
  }
  return true;
}

// Runs of a shared boundary tried, longest first, where the welded union fails (chart_join.h).
constexpr std::size_t kRunsTried = 3;
// A chart under this many times MergeLimits::smallArea is medium.
constexpr double kMediumFactor = 16.0;

// Texels of the chart's bounding rectangle with one texel more on every side: what it costs in
// the atlas with padding 2 (each chart's mask grown by one texel must not meet another's).
double paddedTexels(glm::dvec2 sides, double texelSize) {
  const auto cells = [&](double side) { return std::max(1.0, std::ceil(side / texelSize - 0.01)); };
  return (cells(sides.x) + 2.0) * (cells(sides.y) + 2.0);
}

// One conformal map of both charts (d's triangles, then c's): welded wherever they share
// positions, else joined along the longest run of their shared boundary (chart_join.h); one map
// when that run is all they share.
FlatGroup flattenUnion(const WorldMesh& mesh, const FlatGroup& d, const FlatGroup& c,
                       double areaBound) {
  FlatGroup both{d.triangles, {}};
  both.triangles.insert(both.triangles.end(), c.triangles.begin(), c.triangles.end());
  const std::vector<JoinedCharts> joins =
      joinAlongRuns(mesh, d.triangles, d.flat.cornerUv, c.triangles, c.flat.cornerUv, kRunsTried);
  if (joins.empty() || !joins.front().everyEdge) {
    both.flat = flattenConformal(mesh, both.triangles, 1.0f);
    if (!both.flat.cornerUv.empty() &&
        areaScalesBounded(mesh, both.triangles, both.flat.cornerUv, areaBound))
      return both;
  }
  for (const JoinedCharts& joined : joins) {
    both.flat = flattenConformal(mesh, joined.triangles, joined.cornerVertex, 1.0f);
    if (!both.flat.cornerUv.empty() &&
        areaScalesBounded(mesh, both.triangles, both.flat.cornerUv, areaBound))
      return both;
  }
  both.flat.cornerUv.clear();
  return both;
}

}  // namespace

glm::dvec2 boundingSides(const std::vector<glm::vec2>& cornerUv) {
  std::vector<glm::vec2> turned = cornerUv;
  orientChart(turned);
  glm::vec2 hi(0.0f);
  for (const glm::vec2 p : turned) hi = glm::max(hi, p);
  return {std::min(hi.x, hi.y), std::max(hi.x, hi.y)};
}

std::vector<FlatGroup> mergeSmallCharts(const WorldMesh& mesh, std::vector<FlatGroup> groups,
                                        const std::vector<ChartContact>& contacts,
                                        const MergeLimits& limits) {
  const std::size_t n = groups.size();
  std::vector<double> area(n, 0.0);
  std::vector<glm::dvec2> sides(n, glm::dvec2(0.0));
  for (std::size_t c = 0; c < n; ++c) {
    for (const uint32_t t : groups[c].triangles) area[c] += mesh.area(t);
    if (!groups[c].flat.cornerUv.empty()) sides[c] = boundingSides(groups[c].flat.cornerUv);
  }
  const auto tiny = [&](std::size_t c, std::size_t d) {
    return area[c] < limits.smallArea && area[d] < 8.0 * limits.smallArea;
  };
  const auto narrow = [&](std::size_t c) { return sides[c].x <= limits.texelSize; };
  const auto medium = [&](std::size_t c) { return area[c] < kMediumFactor * limits.smallArea; };
  struct Shared {
    double length = 0.0, fold = 0.0;
  };
  std::vector<std::map<uint32_t, Shared>> touching(n);  // chart → neighbour → shared edges
  for (const ChartContact& contact : contacts) {
    touching[contact.a][contact.b] = {contact.length, contact.fold};
    touching[contact.b][contact.a] = {contact.length, contact.fold};
  }
  // Which rule lets c join d: 0 none, 1 tiny, 2 narrow or medium (padding must shrink).
  const auto rule = [&](std::size_t c, std::size_t d, const Shared& shared) {
    if (tiny(c, d)) return 1;
    if ((narrow(c) && shared.fold <= limits.narrowFold) ||
        (medium(c) && shared.fold <= limits.mediumFold))
      return 2;
    return 0;
  };
  std::vector<bool> alive(n, true);
  std::vector<uint32_t> order(n);
  for (std::size_t c = 0; c < n; ++c) order[c] = static_cast<uint32_t>(c);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return area[a] < area[b]; });
  for (const uint32_t c : order) {
    if (!alive[c] || groups[c].flat.cornerUv.empty()) continue;
    std::vector<std::pair<double, uint32_t>> candidates;  // (−shared length, neighbour)
    for (const auto& [d, shared] : touching[c])
      if (alive[d] && !groups[d].flat.cornerUv.empty() && rule(c, d, shared) > 0)
        candidates.emplace_back(-shared.length, d);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [negativeLength, d] : candidates) {
      const bool byTinyRule = rule(c, d, touching[c][d]) == 1;
      FlatGroup both = flattenUnion(mesh, groups[d], groups[c], byTinyRule ? 3.0 : 2.0);
      if (both.flat.cornerUv.empty()) continue;
      const glm::dvec2 bothSides = boundingSides(both.flat.cornerUv);
      if (!byTinyRule &&
          paddedTexels(bothSides, limits.texelSize) >
              paddedTexels(sides[c], limits.texelSize) + paddedTexels(sides[d], limits.texelSize))
        continue;
      groups[d] = std::move(both);
      area[d] += area[c];
      sides[d] = bothSides;
      alive[c] = false;
      for (const auto& [e, shared] : touching[c]) {
        if (e == d) continue;
        touching[e].erase(c);
        Shared& de = touching[d][e];
        de.length += shared.length;
        de.fold = std::max(de.fold, shared.fold);
        touching[e][d] = de;
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
