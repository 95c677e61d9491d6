#include "atlas/chart_join.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace bounce {
namespace {

// A turn sharper than this (radians, 45°) at a vertex of the shared boundary ends a run.
constexpr double kMaxRunTurn = 0.785;

using PositionKey = std::array<float, 3>;
using EdgeKey = std::pair<PositionKey, PositionKey>;  // lower position first

PositionKey keyOf(glm::vec3 p) {
  return {p.x, p.y, p.z};
}

// One chart's vertices (corners at one position and one UV) and its boundary edges (used by one
// triangle), keyed by their end positions; an edge key seen twice on the boundary (a seam inside
// the chart) is left out.
struct ChartVertices {
  std::vector<int> cornerVertex;
  std::vector<glm::dvec3> position;
  std::map<EdgeKey, std::pair<int, int>> boundary;  // ends in key order
};

ChartVertices verticesOf(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                         const std::vector<glm::vec2>& uv) {
  ChartVertices chart;
  std::map<std::pair<PositionKey, std::array<float, 2>>, int> index;
  for (std::size_t k = 0; k < 3 * triangles.size(); ++k) {
    const glm::vec3 p = mesh.corner(triangles[k / 3], static_cast<int>(k % 3));
    const auto [it, added] =
        index.try_emplace({keyOf(p), {uv[k].x, uv[k].y}}, static_cast<int>(chart.position.size()));
    if (added) chart.position.emplace_back(p);
    chart.cornerVertex.push_back(it->second);
  }
  std::map<std::pair<int, int>, int> uses;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int j = 0; j < 3; ++j) {
      const int u = chart.cornerVertex[3 * t + j], v = chart.cornerVertex[3 * t + (j + 1) % 3];
      ++uses[{std::min(u, v), std::max(u, v)}];
    }
  std::map<EdgeKey, int> seen;
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    int u = edge.first, v = edge.second;
    PositionKey pu = keyOf(glm::vec3(chart.position[u])), pv = keyOf(glm::vec3(chart.position[v]));
    if (pv < pu) std::swap(u, v), std::swap(pu, pv);
    if (++seen[{pu, pv}] == 1)
      chart.boundary[{pu, pv}] = {u, v};
    else
      chart.boundary.erase({pu, pv});
  }
  return chart;
}

}  // namespace

std::vector<JoinedCharts> joinAlongRuns(const WorldMesh& mesh, const std::vector<uint32_t>& a,
                                        const std::vector<glm::vec2>& aUv,
                                        const std::vector<uint32_t>& b,
                                        const std::vector<glm::vec2>& bUv, std::size_t most) {
  const ChartVertices va = verticesOf(mesh, a, aUv), vb = verticesOf(mesh, b, bUv);
  // Shared boundary edges as pairs of a's vertices, with b's vertex at each end.
  std::map<int, int> bAt;  // a's vertex → b's vertex at its position (on a shared edge)
  std::map<int, std::vector<int>> next;  // a's vertex → a's vertices across shared edges
  for (const auto& [key, ends] : va.boundary) {
    const auto it = vb.boundary.find(key);
    if (it == vb.boundary.end()) continue;
    const auto [u, v] = ends;
    const auto [bu, bv] = it->second;
    if ((bAt.count(u) && bAt[u] != bu) || (bAt.count(v) && bAt[v] != bv)) continue;
    bAt[u] = bu, bAt[v] = bv;
    next[u].push_back(v);
    next[v].push_back(u);
  }
  if (next.empty()) return {};
  // A vertex inside a run has two shared edges turning less than kMaxRunTurn; any other vertex
  // ends the runs through it.
  const auto inside = [&](int v) {
    const std::vector<int>& n = next.at(v);
    if (n.size() != 2) return false;
    const glm::dvec3 in = va.position[v] - va.position[n[0]];
    const glm::dvec3 out = va.position[n[1]] - va.position[v];
    const double cosTurn = glm::dot(in, out) / (glm::length(in) * glm::length(out));
    return cosTurn > std::cos(kMaxRunTurn);
  };
  // Walk every run once (edges marked by their lower vertex first).
  std::map<std::pair<int, int>, bool> walked;
  std::vector<std::pair<double, std::vector<int>>> runs;  // (length, vertices)
  const auto walk = [&](int from, int to) {
    std::vector<int> run{from};
    double length = 0.0;
    while (!walked[{std::min(from, to), std::max(from, to)}]) {
      walked[{std::min(from, to), std::max(from, to)}] = true;
      length += glm::distance(va.position[from], va.position[to]);
      run.push_back(to);
      if (!inside(to)) break;
      const std::vector<int>& n = next.at(to);
      const int after = n[0] == from ? n[1] : n[0];
      from = to, to = after;
    }
    if (length > 0.0) runs.emplace_back(length, std::move(run));
  };
  for (const auto& [v, n] : next)
    if (!inside(v))
      for (const int w : n) walk(v, w);
  for (const auto& [v, n] : next)  // closed loops with no end: start anywhere
    for (const int w : n) walk(v, w);
  // Longest first (ties in walking order, so deterministic).
  std::stable_sort(runs.begin(), runs.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  std::size_t sharedEdges = 0;
  for (const auto& [v, n] : next) sharedEdges += n.size();
  std::vector<JoinedCharts> joins;
  for (std::size_t r = 0; r < runs.size() && r < most; ++r) {
    std::vector<int>& run = runs[r].second;
    // A loop walked whole ends on its first vertex: open it by its last edge (joined on every
    // vertex, a loop's edges would all be joined).
    if (run.size() > 2 && run.front() == run.back()) run.resize(run.size() - 2);
    JoinedCharts joined;
    joined.everyEdge = run.size() == sharedEdges / 2 + 1;
    joined.triangles = a;
    joined.triangles.insert(joined.triangles.end(), b.begin(), b.end());
    std::vector<int> bVertex(vb.position.size(), -1);  // b's vertex → union vertex
    for (const int v : run) bVertex[bAt.at(v)] = v;
    int count = static_cast<int>(va.position.size());
    for (int& id : bVertex)
      if (id < 0) id = count++;
    joined.cornerVertex = va.cornerVertex;
    for (const int v : vb.cornerVertex) joined.cornerVertex.push_back(bVertex[v]);
    joins.push_back(std::move(joined));
  }
  return joins;
}

}  // namespace bounce
