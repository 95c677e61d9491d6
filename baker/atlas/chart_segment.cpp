#include "atlas/chart_segment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>

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

}  // namespace

double WorldMesh::area(std::size_t t) const {
  const glm::dvec3 a(corner(t, 0)), b(corner(t, 1)), c(corner(t, 2));
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

TriangleGroups segmentCharts(const WorldMesh& mesh, const SegmentSettings& settings) {
  TriangleGroups groups;
  const std::size_t triangles = mesh.triangleCount();

  // The half-edge mesh over welded positions (a glTF mesh splits vertices at normal and UV
  // seams; the charts must see through those). A triangle that would make an edge non-manifold
  // is added on its own vertices: it then has no neighbours and becomes a chart of its own.
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
  // OpenMesh reports each refused face on its error stream; refusals are handled below.
  const bool omerrWasEnabled = omerr().is_enabled();
  omerr().disable();
  for (std::size_t t = 0; t < triangles; ++t) {
    std::array<HalfEdgeMesh::VertexHandle, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = vertexAt(mesh.corner(t, k));
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || mesh.area(t) < settings.degenerateArea) {
      groups.degenerate.push_back(static_cast<uint32_t>(t));
      continue;
    }
    auto face = halfEdges.add_face(v[0], v[1], v[2]);
    if (!face.is_valid()) {
      std::array<HalfEdgeMesh::VertexHandle, 3> own;
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 p = mesh.corner(t, k);
        own[k] = halfEdges.add_vertex(HalfEdgeMesh::Point(p.x, p.y, p.z));
      }
      face = halfEdges.add_face(own[0], own[1], own[2]);
    }
    faceTriangle.push_back(static_cast<uint32_t>(t));
  }
  if (omerrWasEnabled) omerr().enable();

  std::vector<glm::dvec3> normal(faceTriangle.size());
  std::vector<double> area(faceTriangle.size());
  for (std::size_t f = 0; f < faceTriangle.size(); ++f) {
    normal[f] = unitNormal(mesh, faceTriangle[f]);
    area[f] = mesh.area(faceTriangle[f]);
  }
  // Seeds: largest triangles first (ties by index, so the result is deterministic).
  std::vector<int> seeds(faceTriangle.size());
  for (std::size_t f = 0; f < seeds.size(); ++f) seeds[f] = static_cast<int>(f);
  std::stable_sort(seeds.begin(), seeds.end(), [&](int a, int b) { return area[a] > area[b]; });

  const double cosCone = std::cos(static_cast<double>(settings.coneHalfAngle));
  const double cosCrease = std::cos(static_cast<double>(settings.creaseAngle));
  std::vector<bool> assigned(faceTriangle.size(), false);
  for (const int seed : seeds) {
    if (assigned[seed]) continue;
    const glm::dvec3 axis = normal[seed];
    std::vector<uint32_t> chart;
    std::deque<int> frontier{seed};
    assigned[seed] = true;
    while (!frontier.empty()) {
      const int f = frontier.front();
      frontier.pop_front();
      chart.push_back(faceTriangle[f]);
      for (auto h : halfEdges.fh_range(halfEdges.face_handle(f))) {
        const auto g = halfEdges.opposite_face_handle(h);
        if (!g.is_valid() || assigned[g.idx()]) continue;
        if (glm::dot(normal[g.idx()], axis) < cosCone) continue;
        if (glm::dot(normal[g.idx()], normal[f]) < cosCrease) continue;
        assigned[g.idx()] = true;
        frontier.push_back(g.idx());
      }
    }
    std::sort(chart.begin(), chart.end());
    groups.charts.push_back(std::move(chart));
  }
  return groups;
}

}  // namespace bounce
