#include "atlas/chart_segment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

namespace bounce {
namespace {

using HalfEdgeMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

glm::dvec3 unitNormal(const WorldMesh& mesh, std::size_t t) {
  const glm::dvec3 a(mesh.corner(t, 0)), b(mesh.corner(t, 1)), c(mesh.corner(t, 2));
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  return len > 0.0 ? n / len : glm::dvec3(0.0);
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// Every normal of a chart lies within halfAngle (radians) of the unit axis.
struct NormalCone {
  glm::dvec3 axis{0, 0, 1};
  double halfAngle = 0.0;
};

// The smallest cone holding both cones.
NormalCone enclosingCone(const NormalCone& a, const NormalCone& b) {
  const double between = angleBetween(a.axis, b.axis);
  if (between + b.halfAngle <= a.halfAngle) return a;
  if (between + a.halfAngle <= b.halfAngle) return b;
  const double halfAngle = 0.5 * (between + a.halfAngle + b.halfAngle);
  if (halfAngle >= 3.14159 || between < 1e-12) return {a.axis, halfAngle};
  // Turn a's axis towards b's by halfAngle − a.halfAngle, in their common plane.
  const glm::dvec3 towards = glm::normalize(b.axis - a.axis * glm::dot(a.axis, b.axis));
  const double turn = halfAngle - a.halfAngle;
  return {glm::normalize(a.axis * std::cos(turn) + towards * std::sin(turn)), halfAngle};
}

}  // namespace

double WorldMesh::area(std::size_t t) const {
  const glm::dvec3 a(corner(t, 0)), b(corner(t, 1)), c(corner(t, 2));
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

TriangleGroups segmentCharts(const WorldMesh& mesh, const SegmentSettings& settings) {
  TriangleGroups groups;
  const std::size_t triangles = mesh.triangleCount();

  // The half-edge mesh over welded positions (a glTF mesh splits vertices at normal and UV
  // seams; the charts must see through those).
  HalfEdgeMesh halfEdges;
  std::map<std::array<float, 3>, HalfEdgeMesh::VertexHandle> welded;
  auto vertexAt = [&](glm::vec3 p) -> HalfEdgeMesh::VertexHandle {
    const std::array<float, 3> key{p.x, p.y, p.z};
    const auto it = welded.find(key);
    if (it != welded.end()) return it->second;
    const auto v = halfEdges.add_vertex(HalfEdgeMesh::Point(p.x, p.y, p.z));
    welded.emplace(key, v);
    return v;
  };
  std::vector<uint32_t> faceTriangle;  // OpenMesh face index → mesh triangle
  std::set<std::pair<int, int>> cut;   // welded vertex pairs (lower first) of cut edges
  const auto edgeKey = [](HalfEdgeMesh::VertexHandle a, HalfEdgeMesh::VertexHandle b) {
    return std::pair<int, int>(std::min(a.idx(), b.idx()), std::max(a.idx(), b.idx()));
  };
  const auto isCut = [&](HalfEdgeMesh::HalfedgeHandle h) {
    return !cut.empty() &&
           cut.count(edgeKey(halfEdges.from_vertex_handle(h), halfEdges.to_vertex_handle(h))) > 0;
  };
  // OpenMesh reports each refused face on its error stream; refusals are handled below.
  const SilencedOpenMeshErrors silenced;
  for (std::size_t t = 0; t < triangles; ++t) {
    // Non-finite corners (never from the loaders, which refuse them) join no chart either.
    if (!(mesh.area(t) >= settings.degenerateArea)) {
      groups.degenerate.push_back(static_cast<uint32_t>(t));
      continue;
    }
    std::array<HalfEdgeMesh::VertexHandle, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = vertexAt(mesh.corner(t, k));
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      groups.degenerate.push_back(static_cast<uint32_t>(t));
      continue;
    }
    // A face OpenMesh refuses (a third face on an edge, a vertex whose fan would not be a
    // disc, or a flipped neighbour) is retried with one corner, then two, then all three on
    // vertices of its own: it keeps as many neighbours as the half-edge structure allows.
    // A cut edge (a wall's foot on this floor, Mesh::cutEdges) bounds every chart.
    if (!mesh.cutEdges.empty())
      for (int k = 0; k < 3; ++k)
        if (mesh.cutEdges[t] & (1u << k)) cut.insert(edgeKey(v[k], v[(k + 1) % 3]));
    auto face = halfEdges.add_face(v[0], v[1], v[2]);
    for (const int own : {1, 2, 4, 3, 5, 6, 7}) {
      if (face.is_valid()) break;
      std::array<HalfEdgeMesh::VertexHandle, 3> corner = v;
      for (int k = 0; k < 3; ++k)
        if (own & (1 << k)) {
          const glm::vec3 p = mesh.corner(t, k);
          corner[k] = halfEdges.add_vertex(HalfEdgeMesh::Point(p.x, p.y, p.z));
        }
      face = halfEdges.add_face(corner[0], corner[1], corner[2]);
    }
    faceTriangle.push_back(static_cast<uint32_t>(t));
  }

  std::vector<glm::dvec3> normal(faceTriangle.size());
  std::vector<double> area(faceTriangle.size());
  for (std::size_t f = 0; f < faceTriangle.size(); ++f) {
    normal[f] = unitNormal(mesh, faceTriangle[f]);
    area[f] = mesh.area(faceTriangle[f]);
  }
  // Triangles by decreasing area (ties by index, so everything below is deterministic).
  std::vector<int> bySize(faceTriangle.size());
  for (std::size_t f = 0; f < bySize.size(); ++f) bySize[f] = static_cast<int>(f);
  std::stable_sort(bySize.begin(), bySize.end(), [&](int a, int b) { return area[a] > area[b]; });

  const double cosCone = std::cos(static_cast<double>(settings.coneHalfAngle));
  const double cosCrease = std::cos(static_cast<double>(settings.creaseAngle));
  std::vector<int> faceChart;
  std::vector<glm::dvec3> axes;  // per chart: its seed's normal, the axis of its cone
  // Grows the charts of `seeds` together, each towards the triangles best aligned with its axis
  // first; triangles left over seed further charts, largest first.
  auto grow = [&](const std::vector<int>& seeds) {
    faceChart.assign(faceTriangle.size(), -1);
    axes.clear();
    std::set<std::tuple<double, int, int>> frontier;  // (−alignment, chart, face)
    auto flood = [&] {
      while (!frontier.empty()) {
        const auto [negativeAlignment, c, f] = *frontier.begin();
        frontier.erase(frontier.begin());
        if (faceChart[f] >= 0) continue;
        faceChart[f] = c;
        for (auto h : halfEdges.fh_range(halfEdges.face_handle(f))) {
          const auto g = halfEdges.opposite_face_handle(h);
          if (!g.is_valid() || faceChart[g.idx()] >= 0 || isCut(h)) continue;
          const double alignment = glm::dot(normal[g.idx()], axes[c]);
          if (alignment < cosCone) continue;
          if (glm::dot(normal[g.idx()], normal[f]) < cosCrease) continue;
          frontier.emplace(-alignment, c, g.idx());
        }
      }
    };
    for (const int seed : seeds) {
      frontier.emplace(-1.0, static_cast<int>(axes.size()), seed);
      axes.push_back(normal[seed]);
    }
    flood();
    for (const int f : bySize)
      if (faceChart[f] < 0) {
        frontier.emplace(-1.0, static_cast<int>(axes.size()), f);
        axes.push_back(normal[f]);
        flood();
      }
  };
  grow({});
  // Lloyd iterations: each chart re-seeded at the triangle closest to its mean normal, so seeds
  // move to the middle of their regions and fragments between charts shrink.
  for (int iteration = 0; iteration < 3; ++iteration) {
    std::vector<glm::dvec3> mean(axes.size(), glm::dvec3(0.0));
    for (std::size_t f = 0; f < faceChart.size(); ++f) mean[faceChart[f]] += normal[f] * area[f];
    std::vector<int> seeds(axes.size(), -1);
    std::vector<double> best(axes.size(), -2.0);
    for (std::size_t f = 0; f < faceChart.size(); ++f) {
      const int c = faceChart[f];
      const double alignment = glm::dot(normal[f], glm::normalize(mean[c]));
      if (alignment > best[c]) best[c] = alignment, seeds[c] = static_cast<int>(f);
    }
    grow(seeds);
  }
  std::vector<std::vector<int>> chartFaces(axes.size());
  std::vector<NormalCone> cones(axes.size());
  for (std::size_t c = 0; c < axes.size(); ++c) cones[c].axis = axes[c];
  for (std::size_t f = 0; f < faceChart.size(); ++f) {
    const int c = faceChart[f];
    chartFaces[c].push_back(static_cast<int>(f));
    cones[c].halfAngle = std::max(cones[c].halfAngle, angleBetween(normal[f], axes[c]));
  }

  // Merging: growth from the largest triangles leaves fragments between the charts of a curved
  // surface. Smallest first, a chart joins the neighbour (of at least its area) it shares the
  // longest smooth boundary with, when the bounding cone of both normals stays within
  // mergeHalfAngle (still a height field over the cone's axis, which the flattening needs).
  std::vector<double> chartArea(chartFaces.size(), 0.0);
  for (std::size_t c = 0; c < chartFaces.size(); ++c)
    for (const int f : chartFaces[c]) chartArea[c] += area[f];
  std::vector<int> order(chartFaces.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = static_cast<int>(c);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return chartArea[a] < chartArea[b]; });
  for (const int c : order) {
    std::map<int, double> shared;  // neighbouring chart → length of the smooth shared boundary
    for (const int f : chartFaces[c])
      for (auto h : halfEdges.fh_range(halfEdges.face_handle(f))) {
        const auto g = halfEdges.opposite_face_handle(h);
        if (!g.is_valid() || faceChart[g.idx()] == c || isCut(h)) continue;
        if (glm::dot(normal[g.idx()], normal[f]) < cosCrease) continue;
        shared[faceChart[g.idx()]] += static_cast<double>(halfEdges.calc_edge_length(h));
      }
    std::vector<std::pair<double, int>> candidates;
    for (const auto& [d, length] : shared)
      if (chartArea[d] >= chartArea[c]) candidates.emplace_back(-length, d);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [negativeLength, d] : candidates) {
      const NormalCone merged = enclosingCone(cones[d], cones[c]);
      if (merged.halfAngle > static_cast<double>(settings.mergeHalfAngle)) continue;
      for (const int f : chartFaces[c]) faceChart[f] = d;
      chartFaces[d].insert(chartFaces[d].end(), chartFaces[c].begin(), chartFaces[c].end());
      chartFaces[c].clear();
      chartArea[d] += chartArea[c];
      chartArea[c] = 0.0;
      cones[d] = merged;
      break;
    }
  }
  std::vector<int> finalIndex(chartFaces.size(), -1);
  for (std::size_t c = 0; c < chartFaces.size(); ++c) {
    if (chartFaces[c].empty()) continue;
    finalIndex[c] = static_cast<int>(groups.charts.size());
    std::vector<uint32_t> chart;
    for (const int f : chartFaces[c]) chart.push_back(faceTriangle[f]);
    std::sort(chart.begin(), chart.end());
    groups.charts.push_back(std::move(chart));
  }
  std::map<std::pair<int, int>, std::pair<double, double>> contact;  // → (length, fold)
  for (std::size_t f = 0; f < faceChart.size(); ++f)
    for (auto h : halfEdges.fh_range(halfEdges.face_handle(static_cast<int>(f)))) {
      const auto g = halfEdges.opposite_face_handle(h);
      if (!g.is_valid() || isCut(h)) continue;  // charts never merge across a cut
      const int a = finalIndex[faceChart[f]], b = finalIndex[faceChart[g.idx()]];
      if (a >= b) continue;
      auto& [length, fold] = contact[{a, b}];
      length += static_cast<double>(halfEdges.calc_edge_length(h));
      fold = std::max(fold, angleBetween(normal[f], normal[g.idx()]));
    }
  for (const auto& [pair, shared] : contact)
    groups.contacts.push_back({static_cast<uint32_t>(pair.first),
                               static_cast<uint32_t>(pair.second), shared.first, shared.second});
  return groups;
}

namespace {
std::mutex silencedLock;
int silencedCount = 0;             // guarded by silencedLock
bool enabledBeforeSilence = true;  // guarded by silencedLock
}  // namespace

SilencedOpenMeshErrors::SilencedOpenMeshErrors() {
  const std::lock_guard<std::mutex> hold(silencedLock);
  if (silencedCount++ == 0) {
    enabledBeforeSilence = omerr().is_enabled();
    omerr().disable();
  }
}

SilencedOpenMeshErrors::~SilencedOpenMeshErrors() {
  const std::lock_guard<std::mutex> hold(silencedLock);
  if (--silencedCount == 0 && enabledBeforeSilence) omerr().enable();
}

}  // namespace bounce
