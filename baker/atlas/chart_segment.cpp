#include "atlas/chart_segment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include <tbb/parallel_for.h>
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

namespace {

// The faces of the half-edge mesh and what segmentation reads of them (indices: OpenMesh faces).
struct FaceData {
  const HalfEdgeMesh& halfEdges;
  const std::vector<glm::dvec3>& normal;
  const std::vector<double>& area;           // m²
  const std::vector<int>& rank;              // place in the order by decreasing area, ties by index
  const std::set<std::pair<int, int>>& cut;  // welded vertex pairs (lower first) of cut edges
  bool isCut(HalfEdgeMesh::HalfedgeHandle h) const {
    if (cut.empty()) return false;
    const int a = halfEdges.from_vertex_handle(h).idx(), b = halfEdges.to_vertex_handle(h).idx();
    return cut.count({std::min(a, b), std::max(a, b)}) > 0;
  }
  // The face across h, when it exists and the edge is not cut (charts grow only there).
  int across(HalfEdgeMesh::HalfedgeHandle h) const {
    const auto g = halfEdges.opposite_face_handle(h);
    return g.is_valid() && !isCut(h) ? g.idx() : -1;
  }
};

// Faces joined across uncut edges: each component's faces in increasing order, components in the
// order of their first face.
std::vector<std::vector<int>> edgeComponents(const FaceData& faces) {
  const std::size_t n = faces.area.size();
  std::vector<int> component(n, -1);
  std::vector<std::vector<int>> components;
  for (std::size_t start = 0; start < n; ++start) {
    if (component[start] >= 0) continue;
    const int k = static_cast<int>(components.size());
    std::vector<int> members{static_cast<int>(start)};
    component[start] = k;
    for (std::size_t next = 0; next < members.size(); ++next)
      for (auto h : faces.halfEdges.fh_range(faces.halfEdges.face_handle(members[next]))) {
        const int g = faces.across(h);
        if (g >= 0 && component[g] < 0) {
          component[g] = k;
          members.push_back(g);
        }
      }
    std::sort(members.begin(), members.end());
    components.push_back(std::move(members));
  }
  return components;
}

// A chart's place in the numbering of one pass over all faces: charts are numbered as they are
// made, those of the first growth by their seed's place in bySize, those a Lloyd iteration adds
// after every earlier one, again by seed. (iteration, seed's place in bySize).
using ChartKey = std::pair<int, int>;

// One component's charts (OpenMesh faces, in the component's chart order), their keys, and their
// contacts (indices into its charts, sorted by (a, b)).
struct ComponentCharts {
  std::vector<std::vector<int>> charts;
  std::vector<ChartKey> keys;
  std::vector<ChartContact> contacts;
};

// `localOf` holds each face's index in its component's `members`.
ComponentCharts segmentComponent(const FaceData& faces, const std::vector<int>& members,
                                 const std::vector<int>& localOf, const SegmentSettings& settings) {
  const HalfEdgeMesh& halfEdges = faces.halfEdges;
  const std::vector<glm::dvec3>& normal = faces.normal;
  // Faces are numbered within the component (`localOf`, in the faces' order).
  const auto local = [&](int face) { return localOf[face]; };
  std::vector<int> bySize(members.size());  // the component's faces by decreasing area, local
  for (std::size_t f = 0; f < members.size(); ++f) bySize[f] = static_cast<int>(f);
  std::sort(bySize.begin(), bySize.end(),
            [&](int a, int b) { return faces.rank[members[a]] < faces.rank[members[b]]; });

  const double cosCone = std::cos(static_cast<double>(settings.coneHalfAngle));
  const double cosCrease = std::cos(static_cast<double>(settings.creaseAngle));
  std::vector<int> faceChart;
  std::vector<glm::dvec3> axes;  // per chart: its seed's normal, the axis of its cone
  std::vector<ChartKey> keys;    // per chart
  // Grows the charts of `seeds` together, each towards the triangles best aligned with its axis
  // first; triangles left over seed further charts, largest first.
  auto grow = [&](const std::vector<int>& seeds, int iteration) {
    faceChart.assign(members.size(), -1);
    axes.clear();
    std::vector<ChartKey> seedKeys = std::move(keys);
    keys.clear();
    std::set<std::tuple<double, int, int>> frontier;  // (−alignment, chart, face)
    auto flood = [&] {
      while (!frontier.empty()) {
        const auto [negativeAlignment, c, f] = *frontier.begin();
        frontier.erase(frontier.begin());
        if (faceChart[f] >= 0) continue;
        faceChart[f] = c;
        for (auto h : halfEdges.fh_range(halfEdges.face_handle(members[f]))) {
          const int across = faces.across(h);
          if (across < 0) continue;
          const int g = local(across);
          if (faceChart[g] >= 0) continue;
          const double alignment = glm::dot(normal[members[g]], axes[c]);
          if (alignment < cosCone) continue;
          if (glm::dot(normal[members[g]], normal[members[f]]) < cosCrease) continue;
          frontier.emplace(-alignment, c, g);
        }
      }
    };
    for (std::size_t k = 0; k < seeds.size(); ++k) {
      frontier.emplace(-1.0, static_cast<int>(axes.size()), seeds[k]);
      axes.push_back(normal[members[seeds[k]]]);
      keys.push_back(seedKeys[k]);
    }
    flood();
    for (const int f : bySize)
      if (faceChart[f] < 0) {
        frontier.emplace(-1.0, static_cast<int>(axes.size()), f);
        axes.push_back(normal[members[f]]);
        keys.emplace_back(iteration, faces.rank[members[f]]);
        flood();
      }
  };
  grow({}, 0);
  // Lloyd iterations: each chart re-seeded at the triangle closest to its mean normal, so seeds
  // move to the middle of their regions and fragments between charts shrink.
  for (int iteration = 0; iteration < 3; ++iteration) {
    std::vector<glm::dvec3> mean(axes.size(), glm::dvec3(0.0));
    for (std::size_t f = 0; f < faceChart.size(); ++f)
      mean[faceChart[f]] += normal[members[f]] * faces.area[members[f]];
    std::vector<int> seeds(axes.size(), -1);
    std::vector<double> best(axes.size(), -2.0);
    for (std::size_t f = 0; f < faceChart.size(); ++f) {
      const int c = faceChart[f];
      const double alignment = glm::dot(normal[members[f]], glm::normalize(mean[c]));
      if (alignment > best[c]) best[c] = alignment, seeds[c] = static_cast<int>(f);
    }
    grow(seeds, iteration + 1);
  }
  std::vector<std::vector<int>> chartFaces(axes.size());
  std::vector<NormalCone> cones(axes.size());
  for (std::size_t c = 0; c < axes.size(); ++c) cones[c].axis = axes[c];
  for (std::size_t f = 0; f < faceChart.size(); ++f) {
    const int c = faceChart[f];
    chartFaces[c].push_back(static_cast<int>(f));
    cones[c].halfAngle = std::max(cones[c].halfAngle, angleBetween(normal[members[f]], axes[c]));
  }

  // Merging: growth from the largest triangles leaves fragments between the charts of a curved
  // surface. Smallest first, a chart joins the neighbour (of at least its area) it shares the
  // longest smooth boundary with, when the bounding cone of both normals stays within
  // mergeHalfAngle (still a height field over the cone's axis, which the flattening needs).
  std::vector<double> chartArea(chartFaces.size(), 0.0);
  for (std::size_t c = 0; c < chartFaces.size(); ++c)
    for (const int f : chartFaces[c]) chartArea[c] += faces.area[members[f]];
  std::vector<int> order(chartFaces.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = static_cast<int>(c);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return chartArea[a] < chartArea[b]; });
  for (const int c : order) {
    std::map<int, double> shared;  // neighbouring chart → length of the smooth shared boundary
    for (const int f : chartFaces[c])
      for (auto h : halfEdges.fh_range(halfEdges.face_handle(members[f]))) {
        const int across = faces.across(h);
        if (across < 0) continue;
        const int g = local(across);
        if (faceChart[g] == c) continue;
        if (glm::dot(normal[members[g]], normal[members[f]]) < cosCrease) continue;
        shared[faceChart[g]] += static_cast<double>(halfEdges.calc_edge_length(h));
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
  ComponentCharts result;
  std::vector<int> finalIndex(chartFaces.size(), -1);
  for (std::size_t c = 0; c < chartFaces.size(); ++c) {
    if (chartFaces[c].empty()) continue;
    finalIndex[c] = static_cast<int>(result.charts.size());
    std::vector<int> chart;
    for (const int f : chartFaces[c]) chart.push_back(members[f]);
    result.charts.push_back(std::move(chart));
    result.keys.push_back(keys[c]);
  }
  std::map<std::pair<int, int>, std::pair<double, double>> contact;  // → (length, fold)
  for (std::size_t f = 0; f < faceChart.size(); ++f)
    for (auto h : halfEdges.fh_range(halfEdges.face_handle(members[f]))) {
      const int across = faces.across(h);
      if (across < 0) continue;  // charts never merge across a cut
      const int g = local(across);
      const int a = finalIndex[faceChart[f]], b = finalIndex[faceChart[g]];
      if (a >= b) continue;
      auto& [length, fold] = contact[{a, b}];
      length += static_cast<double>(halfEdges.calc_edge_length(h));
      fold = std::max(fold, angleBetween(normal[members[f]], normal[members[g]]));
    }
  for (const auto& [pair, shared] : contact)
    result.contacts.push_back({static_cast<uint32_t>(pair.first),
                               static_cast<uint32_t>(pair.second), shared.first, shared.second});
  return result;
}

}  // namespace

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
  std::vector<int> rank(bySize.size());
  for (std::size_t r = 0; r < bySize.size(); ++r) rank[bySize[r]] = static_cast<int>(r);
  const FaceData faces{halfEdges, normal, area, rank, cut};

  // Charts grow, merge and touch only across uncut edges between faces: each component of faces
  // so joined is segmented on its own (in parallel), and the charts are numbered as one pass
  // over all faces numbers them, by their keys.
  const std::vector<std::vector<int>> components = edgeComponents(faces);
  std::vector<int> localOf(faceTriangle.size());
  for (const std::vector<int>& members : components)
    for (std::size_t f = 0; f < members.size(); ++f) localOf[members[f]] = static_cast<int>(f);
  std::vector<ComponentCharts> segmented(components.size());
  tbb::parallel_for(std::size_t{0}, components.size(), [&](std::size_t k) {
    segmented[k] = segmentComponent(faces, components[k], localOf, settings);
  });
  struct Numbered {
    ChartKey key;
    uint32_t component = 0, chart = 0;
  };
  std::vector<Numbered> numbered;
  for (uint32_t k = 0; k < segmented.size(); ++k)
    for (uint32_t c = 0; c < segmented[k].charts.size(); ++c)
      numbered.push_back({segmented[k].keys[c], k, c});
  std::sort(numbered.begin(), numbered.end(),
            [](const Numbered& a, const Numbered& b) { return a.key < b.key; });
  std::vector<std::vector<uint32_t>> finalIndex(segmented.size());
  for (uint32_t k = 0; k < segmented.size(); ++k) finalIndex[k].resize(segmented[k].charts.size());
  for (const Numbered& n : numbered) {
    finalIndex[n.component][n.chart] = static_cast<uint32_t>(groups.charts.size());
    std::vector<uint32_t> chart;
    for (const int f : segmented[n.component].charts[n.chart]) chart.push_back(faceTriangle[f]);
    std::sort(chart.begin(), chart.end());
    groups.charts.push_back(std::move(chart));
  }
  for (uint32_t k = 0; k < segmented.size(); ++k)
    for (ChartContact contact : segmented[k].contacts) {
      contact.a = finalIndex[k][contact.a];
      contact.b = finalIndex[k][contact.b];
      groups.contacts.push_back(contact);
    }
  std::sort(groups.contacts.begin(), groups.contacts.end(),
            [](const ChartContact& x, const ChartContact& y) {
              return std::pair(x.a, x.b) < std::pair(y.a, y.b);
            });
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
