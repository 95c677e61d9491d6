#include "scene/crossing_cuts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace bounce {
namespace {

// Metres: a point this close to a plane lies on it (a wall thinner than this is not separated).
constexpr double kOnPlane = 1e-5;
// Planes whose normals are closer than this cosine are parallel: they never cut each other.
constexpr double kParallelCosine = 0.99985;  // 1°

struct WorldTriangle {
  std::array<glm::dvec3, 3> p;
  glm::dvec3 n{0.0};  // unit normal
  double d = 0.0;     // plane: dot(n, x) = d
  glm::dvec3 lo{0.0}, hi{0.0};
  uint32_t instance = 0, triangle = 0;
};

WorldTriangle worldTriangle(const Scene& scene, uint32_t i, uint32_t t) {
  const Instance& instance = scene.instances[i];
  const Mesh& mesh = scene.meshes[instance.mesh];
  WorldTriangle w;
  w.instance = i, w.triangle = t;
  for (int k = 0; k < 3; ++k)
    w.p[k] = glm::dvec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[3 * t + k]], 1));
  const glm::dvec3 n = glm::cross(w.p[1] - w.p[0], w.p[2] - w.p[0]);
  const double len = glm::length(n);
  w.n = len > 0.0 ? n / len : glm::dvec3(0.0);
  w.d = glm::dot(w.n, w.p[0]);
  w.lo = glm::min(w.p[0], glm::min(w.p[1], w.p[2]));
  w.hi = glm::max(w.p[0], glm::max(w.p[1], w.p[2]));
  return w;
}

// Static triangles in a bounding-box tree (median splits, small leaves): the receiving
// triangles ask which triangles' boxes overlap theirs. A tree, not a grid: real scenes hold
// dense clusters (a detailed object of 100k sub-millimetre triangles) next to room-sized quads.
// The two halves of a node are built in parallel: its nodes are laid out in depth-first order
// (the left child next, the right one after the left's subtree), so the tree, and the order in
// which near() finds triangles, do not depend on the threads.
class TriangleTree {
 public:
  explicit TriangleTree(std::vector<WorldTriangle> triangles) : triangles_(std::move(triangles)) {
    order_.reserve(triangles_.size());
    for (uint32_t i = 0; i < triangles_.size(); ++i) order_.push_back(i);
    if (order_.empty()) return;
    nodes_.resize(nodeCount(static_cast<uint32_t>(order_.size())));
    build(0, 0, static_cast<uint32_t>(order_.size()));
  }
  const std::vector<WorldTriangle>& triangles() const { return triangles_; }
  // Triangles whose boxes overlap [lo, hi] grown by kOnPlane.
  std::vector<uint32_t> near(const glm::dvec3& lo, const glm::dvec3& hi) const {
    std::vector<uint32_t> found;
    if (nodes_.empty()) return found;
    const glm::dvec3 a = lo - kOnPlane, b = hi + kOnPlane;
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
      const uint32_t index = stack.back();
      const Node& node = nodes_[index];
      stack.pop_back();
      if (glm::any(glm::lessThan(node.hi, a)) || glm::any(glm::greaterThan(node.lo, b))) continue;
      if (node.count > 0) {
        for (uint32_t k = node.first; k < node.first + node.count; ++k) {
          const WorldTriangle& w = triangles_[order_[k]];
          if (!glm::any(glm::lessThan(w.hi, a)) && !glm::any(glm::greaterThan(w.lo, b)))
            found.push_back(order_[k]);
        }
      } else {
        stack.push_back(index + 1);
        stack.push_back(node.first);
      }
    }
    return found;
  }

 private:
  struct Node {
    glm::dvec3 lo{0.0}, hi{0.0};
    uint32_t first = 0;  // leaf: into order_; inner: the right child (the left one follows it)
    uint32_t count = 0;  // triangles in a leaf, 0 for an inner node
  };
  static constexpr uint32_t kLeafSize = 4;
  // Below this many triangles a node's halves are built on the calling thread.
  static constexpr uint32_t kParallelSize = 4096;
  // Nodes of the tree over n triangles: leaves of at most kLeafSize, halves split at n / 2.
  static uint32_t nodeCount(uint32_t n) {
    return n <= kLeafSize ? 1 : 1 + nodeCount(n / 2) + nodeCount(n - n / 2);
  }
  // Fills node `index` with triangles order_[from, to), its subtree at the indices after it.
  void build(uint32_t index, uint32_t from, uint32_t to) {
    glm::dvec3 lo(1e300), hi(-1e300), clo(1e300), chi(-1e300);
    for (uint32_t k = from; k < to; ++k) {
      const WorldTriangle& w = triangles_[order_[k]];
      lo = glm::min(lo, w.lo), hi = glm::max(hi, w.hi);
      const glm::dvec3 c = 0.5 * (w.lo + w.hi);
      clo = glm::min(clo, c), chi = glm::max(chi, c);
    }
    nodes_[index].lo = lo, nodes_[index].hi = hi;
    if (to - from <= kLeafSize) {
      nodes_[index].first = from, nodes_[index].count = to - from;
      return;
    }
    const glm::dvec3 extent = chi - clo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const uint32_t middle = from + (to - from) / 2;
    std::nth_element(order_.begin() + from, order_.begin() + middle, order_.begin() + to,
                     [&](uint32_t p, uint32_t q) {
                       return triangles_[p].lo[axis] + triangles_[p].hi[axis] <
                              triangles_[q].lo[axis] + triangles_[q].hi[axis];
                     });
    const uint32_t right = index + 1 + nodeCount(middle - from);
    nodes_[index].first = right;
    if (to - from < kParallelSize) {
      build(index + 1, from, middle);
      build(right, middle, to);
      return;
    }
    tbb::parallel_invoke([&] { build(index + 1, from, middle); },
                         [&] { build(right, middle, to); });
  }
  std::vector<WorldTriangle> triangles_;
  std::vector<uint32_t> order_;
  std::vector<Node> nodes_;
};

// The interval (along unit direction u) where the plane dot(n, x) = d meets triangle p.
bool planeInterval(const std::array<glm::dvec3, 3>& p, const glm::dvec3& n, double d,
                   const glm::dvec3& u, double& s0, double& s1) {
  std::array<double, 3> dist{};
  for (int k = 0; k < 3; ++k) dist[k] = glm::dot(n, p[k]) - d;
  s0 = 1e300, s1 = -1e300;
  auto add = [&](const glm::dvec3& x) {
    const double s = glm::dot(u, x);
    s0 = std::min(s0, s), s1 = std::max(s1, s);
  };
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (std::abs(dist[k]) <= kOnPlane) add(p[k]);
    if ((dist[k] > kOnPlane && dist[j] < -kOnPlane) || (dist[k] < -kOnPlane && dist[j] > kOnPlane))
      add(p[k] + (p[j] - p[k]) * (dist[k] / (dist[k] - dist[j])));
  }
  return s1 - s0 > kOnPlane;
}

bool sharesAnEdge(const WorldTriangle& a, const WorldTriangle& b) {
  int shared = 0;
  for (const glm::dvec3& p : a.p)
    for (const glm::dvec3& q : b.p) shared += p == q ? 1 : 0;
  return shared >= 2;
}

// The point x (on or near b's plane) lies inside triangle b, within kOnPlane.
bool onTriangle(const WorldTriangle& b, const glm::dvec3& x) {
  if (std::abs(glm::dot(b.n, x) - b.d) > kOnPlane) return false;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 e = b.p[(k + 1) % 3] - b.p[k];
    const glm::dvec3 inward = glm::normalize(glm::cross(b.n, e));
    if (glm::dot(inward, x - b.p[k]) < -kOnPlane) return false;
  }
  return true;
}

// The crossings of T in one plane: the plane, T's chord along it and what covers the chord.
struct CrossingPlane {
  glm::dvec3 n{0.0};
  double d = 0.0;
  glm::dvec3 u{0.0};          // unit direction of the line, along T's plane and this one
  double c0 = 0.0, c1 = 0.0;  // T's chord along u
  // The line (T's plane and this one, each to 1e-4) that T's neighbours on it share.
  std::array<int64_t, 8> line{};
  std::vector<std::pair<double, double>> covered;  // intervals of crossing triangles
  std::vector<uint32_t> crossers;                  // indices into the tree
  double coveredLength() const {
    std::vector<std::pair<double, double>> sorted = covered;
    std::sort(sorted.begin(), sorted.end());
    double length = 0.0, end = -1e300;
    for (const auto& [a, b] : sorted) {
      const double from = std::max(a, end);
      if (b > from) length += b - from;
      end = std::max(end, b);
    }
    return length;
  }
};

// A vertex of a piece of T, by its barycentric coordinates in T (exact zeros on T's edges).
using Bary = std::array<double, 3>;

glm::dvec3 at(const WorldTriangle& t, const Bary& b) {
  return t.p[0] * b[0] + t.p[1] * b[1] + t.p[2] * b[2];
}

// Splits convex polygon `poly` by the plane; the crossing point on an edge is computed from the
// edge's endpoints in one order whichever piece asks, so neighbouring pieces share it exactly.
void split(const WorldTriangle& t, const std::vector<Bary>& poly, const glm::dvec3& n, double d,
           std::vector<std::vector<Bary>>& out) {
  std::vector<double> dist;
  bool below = false, above = false;
  for (const Bary& b : poly) {
    dist.push_back(glm::dot(n, at(t, b)) - d);
    below = below || dist.back() < -kOnPlane;
    above = above || dist.back() > kOnPlane;
  }
  if (!below || !above) {
    out.push_back(poly);
    return;
  }
  std::vector<Bary> neg, pos;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const std::size_t j = (k + 1) % poly.size();
    const double dk = std::abs(dist[k]) <= kOnPlane ? 0.0 : dist[k];
    const double dj = std::abs(dist[j]) <= kOnPlane ? 0.0 : dist[j];
    if (dk <= 0.0) neg.push_back(poly[k]);
    if (dk >= 0.0) pos.push_back(poly[k]);
    if ((dk < 0.0 && dj > 0.0) || (dk > 0.0 && dj < 0.0)) {
      const bool flip = poly[j] < poly[k];
      const Bary& a = flip ? poly[j] : poly[k];
      const Bary& b = flip ? poly[k] : poly[j];
      const double da = flip ? dj : dk, db = flip ? dk : dj;
      const double s = da / (da - db);
      Bary x{};
      for (int c = 0; c < 3; ++c) x[c] = a[c] == b[c] ? a[c] : a[c] + s * (b[c] - a[c]);
      neg.push_back(x);
      pos.push_back(x);
    }
  }
  out.push_back(std::move(neg));
  out.push_back(std::move(pos));
}

// Adds the split pieces of one mesh's triangles, reusing a vertex on an original edge where a
// neighbouring triangle already made one there.
class MeshCutter {
 public:
  explicit MeshCutter(Mesh& mesh) : mesh_(mesh) {}
  uint32_t vertex(uint32_t t, const Bary& b, const WorldTriangle& world) {
    const uint32_t* corner = &mesh_.indices[3 * t];
    for (int k = 0; k < 3; ++k)
      if (b[k] == 1.0 && b[(k + 1) % 3] == 0.0 && b[(k + 2) % 3] == 0.0) return corner[k];
    for (int k = 0; k < 3; ++k) {
      if (b[k] != 0.0) continue;
      // On the edge between corners (k+1) and (k+2): keyed by its vertex pair, lower first.
      uint32_t i = corner[(k + 1) % 3], j = corner[(k + 2) % 3];
      double s = b[(k + 2) % 3];
      if (j < i) std::swap(i, j), s = 1.0 - s;
      const double length = glm::length(world.p[(k + 2) % 3] - world.p[(k + 1) % 3]);
      for (const auto& [s2, v] : onEdge_[{i, j}])
        if (std::abs(s2 - s) * length <= kOnPlane) return v;
      const uint32_t v = add(t, b);
      onEdge_[{i, j}].emplace_back(s, v);
      return v;
    }
    const auto [it, added] = inside_.try_emplace({t, b}, 0u);
    if (added) it->second = add(t, b);
    return it->second;
  }

 private:
  uint32_t add(uint32_t t, const Bary& b) {
    const uint32_t* c = &mesh_.indices[3 * t];
    const auto mix = [&](const auto& values) {
      using V = std::decay_t<decltype(values[0])>;
      V sum(0.0f);
      for (int k = 0; k < 3; ++k) sum += values[c[k]] * static_cast<float>(b[k]);
      return sum;
    };
    const auto v = static_cast<uint32_t>(mesh_.positions.size());
    const glm::vec3 position = mix(mesh_.positions), normal = mix(mesh_.normals);
    const glm::vec2 uv0 = mesh_.uv0.empty() ? glm::vec2(0) : mix(mesh_.uv0);
    const glm::vec2 uv1 = mesh_.uv1.empty() ? glm::vec2(0) : mix(mesh_.uv1);
    mesh_.positions.push_back(position);
    const float len = glm::length(normal);
    mesh_.normals.push_back(len > 0.0f ? normal / len : mesh_.normals[c[0]]);
    if (!mesh_.uv0.empty()) mesh_.uv0.push_back(uv0);
    if (!mesh_.uv1.empty()) mesh_.uv1.push_back(uv1);
    return v;
  }
  Mesh& mesh_;
  std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<double, uint32_t>>> onEdge_;
  std::map<std::pair<uint32_t, Bary>, uint32_t> inside_;
};

// The plane dot(n, x) = d with the largest component of n positive.
std::pair<glm::dvec3, double> canonical(const glm::dvec3& n, double d) {
  const glm::dvec3 a = glm::abs(n);
  const int major = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
  return n[major] < 0.0 ? std::pair(-n, -d) : std::pair(n, d);
}

// Length of the longest run of touching intervals (gaps under 0.1 mm join).
double longestRun(std::vector<std::pair<double, double>> intervals) {
  std::sort(intervals.begin(), intervals.end());
  double longest = 0.0, from = 0.0, to = -1e300;
  for (const auto& [a, b] : intervals) {
    if (a > to + 1e-4) from = a, to = b;
    to = std::max(to, b);
    longest = std::max(longest, to - from);
  }
  return longest;
}

// The planes of the triangles that cross receiving triangle `w`, each with what it covers of
// w's chord.
std::vector<CrossingPlane> crossingPlanes(const WorldTriangle& w, const TriangleTree& tree) {
  std::vector<CrossingPlane> planes;
  for (const uint32_t i : tree.near(w.lo, w.hi)) {
    const WorldTriangle& b = tree.triangles()[i];
    if (b.instance == w.instance && b.triangle == w.triangle) continue;
    if (glm::any(glm::lessThan(b.hi, w.lo - kOnPlane)) ||
        glm::any(glm::greaterThan(b.lo, w.hi + kOnPlane)))
      continue;
    if (std::abs(glm::dot(b.n, w.n)) > kParallelCosine || sharesAnEdge(w, b)) continue;
    // Canonical orientations, so that the crossers of one plane group together and the
    // receivers of one plane share their lines.
    // Plain variables, not a structured binding: clang 14 cannot capture those in a lambda.
    const std::pair<glm::dvec3, double> crosser = canonical(b.n, b.d);
    const glm::dvec3 n = crosser.first;
    const double d = crosser.second;
    const auto [wn, wd] = canonical(w.n, w.d);
    const glm::dvec3 u = glm::normalize(glm::cross(wn, n));
    double s0, s1, c0, c1;
    if (!planeInterval(b.p, w.n, w.d, u, s0, s1)) continue;  // b does not reach T's plane
    if (!planeInterval(w.p, n, d, u, c0, c1)) continue;      // b's plane misses T
    const double from = std::max(s0, c0), to = std::min(s1, c1);
    if (to - from <= kOnPlane) continue;
    auto same = [&](const CrossingPlane& p) {
      return glm::dot(p.n, n) > 1.0 - 1e-9 && std::abs(p.d - d) <= kOnPlane;
    };
    auto it = std::find_if(planes.begin(), planes.end(), same);
    if (it == planes.end()) {
      const auto q = [](double x) { return static_cast<int64_t>(std::llround(x * 1e4)); };
      it = planes.insert(planes.end(), CrossingPlane{n, d, u, c0, c1, {}, {}, {}});
      it->line = {q(wn.x), q(wn.y), q(wn.z), q(wd), q(n.x), q(n.y), q(n.z), q(d)};
    }
    it->covered.emplace_back(from, to);
    it->crossers.push_back(i);
  }
  return planes;
}

// `piece` with a vertex added on each edge along a cut plane wherever a crossing begins or ends
// inside it (a wall's end at a doorway), so that each edge is either crossed or not along all of
// its length. Points on one edge are computed from its endpoints in one order whichever piece
// asks, so the pieces on both sides of the edge share them exactly.
std::vector<Bary> withCrossingEnds(const WorldTriangle& t, const std::vector<Bary>& piece,
                                   const std::vector<CrossingPlane>& planes) {
  std::vector<Bary> ring;
  for (std::size_t k = 0; k < piece.size(); ++k) {
    const Bary& a = piece[k];
    const Bary& b = piece[(k + 1) % piece.size()];
    ring.push_back(a);
    const glm::dvec3 pa = at(t, a), pb = at(t, b);
    const double length = glm::length(pb - pa);
    for (const CrossingPlane& plane : planes) {
      if (std::abs(glm::dot(plane.n, pa) - plane.d) > kOnPlane ||
          std::abs(glm::dot(plane.n, pb) - plane.d) > kOnPlane)
        continue;
      const bool flip = b < a;
      const Bary& lo = flip ? b : a;
      const Bary& hi = flip ? a : b;
      const double s0 = glm::dot(plane.u, at(t, lo)), s1 = glm::dot(plane.u, at(t, hi));
      if (s0 == s1) continue;
      // The ends of the union of the crossings' intervals.
      std::vector<std::pair<double, double>> sorted = plane.covered;
      std::sort(sorted.begin(), sorted.end());
      std::vector<double> ends;
      double from = 0.0, to = -1e300;
      for (const auto& [c0, c1] : sorted) {
        if (c0 > to + kOnPlane) {
          if (to > -1e300) ends.push_back(from), ends.push_back(to);
          from = c0;
        }
        to = std::max(to, c1);
      }
      if (to > -1e300) ends.push_back(from), ends.push_back(to);
      std::vector<double> params;
      for (const double e : ends) {
        const double f = (e - s0) / (s1 - s0);
        if (f * length > kOnPlane && (1.0 - f) * length > kOnPlane) params.push_back(f);
      }
      // Added in order from a to b.
      std::sort(params.begin(), params.end());
      if (flip) std::reverse(params.begin(), params.end());
      for (const double f : params) {
        Bary x{};
        for (int c = 0; c < 3; ++c) x[c] = lo[c] == hi[c] ? lo[c] : lo[c] + f * (hi[c] - lo[c]);
        ring.push_back(x);
      }
      break;  // an edge lies on one crossing plane
    }
  }
  return ring;
}

}  // namespace

CrossingCuts cutAtCrossings(Scene& scene) {
  CrossingCuts result;
  // Every static instance's triangles with an area, in instance order (each instance's in
  // parallel).
  std::vector<std::vector<WorldTriangle>> ofInstance(scene.instances.size());
  tbb::parallel_for(uint32_t{0}, static_cast<uint32_t>(scene.instances.size()), [&](uint32_t i) {
    if (scene.instances[i].mobility != Mobility::Static) return;
    const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
      WorldTriangle w = worldTriangle(scene, i, t);
      if (w.n != glm::dvec3(0.0) &&
          std::isfinite(w.lo.x + w.lo.y + w.lo.z + w.hi.x + w.hi.y + w.hi.z))
        ofInstance[i].push_back(w);
    }
  });
  std::vector<WorldTriangle> all;
  for (std::vector<WorldTriangle>& triangles : ofInstance)
    all.insert(all.end(), triangles.begin(), triangles.end());
  ofInstance.clear();
  if (all.empty()) return result;
  const TriangleTree tree(all);
  std::vector<uint32_t> users(scene.meshes.size(), 0);
  for (const Instance& instance : scene.instances) ++users[instance.mesh];
  std::size_t next = 0;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    // This instance's triangles in the tree's list (added in instance order).
    const std::size_t first = next;
    while (next < all.size() && all[next].instance == i) ++next;
    if (instance.mobility != Mobility::Static || instance.lightmapScale == 0.0f) continue;
    // No line inside a box whose diagonal is under kMinCutLength is long enough to cut: small
    // dense objects (100k triangles in 8 cm) are skipped without a look.
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::size_t k = first; k < next; ++k)
      lo = glm::min(lo, all[k].lo), hi = glm::max(hi, all[k].hi);
    if (first == next || glm::length(hi - lo) < kMinCutLength) continue;
    std::vector<std::pair<uint32_t, std::vector<CrossingPlane>>> cuts;
    // Every crossing line over the instance's triangles: what the crossers cover along it.
    std::map<std::array<int64_t, 8>, std::vector<std::pair<double, double>>> lines;
    // Each triangle's crossing planes on its own (in parallel), then gathered in order.
    std::vector<std::vector<CrossingPlane>> found(next - first);
    tbb::parallel_for(first, next,
                      [&](std::size_t k) { found[k - first] = crossingPlanes(all[k], tree); });
    for (std::size_t k = first; k < next; ++k)
      if (auto planes = std::move(found[k - first]); !planes.empty()) {
        for (const CrossingPlane& p : planes) {
          std::vector<std::pair<double, double>>& line = lines[p.line];
          line.insert(line.end(), p.covered.begin(), p.covered.end());
        }
        cuts.emplace_back(all[k].triangle, std::move(planes));
      }
    std::map<std::array<int64_t, 8>, double> longest;
    for (auto& [line, covered] : lines) longest[line] = longestRun(std::move(covered));
    // The rule: a line with an unbroken crossing at least kMinCutLength long, covering at least
    // kCoverage of this triangle's chord.
    for (auto& [t, planes] : cuts)
      std::erase_if(planes, [&](const CrossingPlane& p) {
        return longest[p.line] < kMinCutLength || p.coveredLength() < kCoverage * (p.c1 - p.c0);
      });
    std::erase_if(cuts, [](const auto& cut) { return cut.second.empty(); });
    if (cuts.empty()) continue;
    if (users[instance.mesh] > 1) {  // the other instances keep the uncut mesh
      --users[instance.mesh];
      scene.meshes.push_back(scene.meshes[instance.mesh]);
      scene.instances[i].mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
      users.push_back(1);
    }
    Mesh& mesh = scene.meshes[scene.instances[i].mesh];
    mesh.cutEdges.resize(mesh.triangleCount(), 0);
    MeshCutter cutter(mesh);
    ++result.cutInstances;
    for (const auto& [t, planes] : cuts) {
      const WorldTriangle w = worldTriangle(scene, i, t);
      std::vector<std::vector<Bary>> pieces{{Bary{1, 0, 0}, Bary{0, 1, 0}, Bary{0, 0, 1}}};
      for (const CrossingPlane& plane : planes) {
        std::vector<std::vector<Bary>> halves;
        for (const auto& piece : pieces) split(w, piece, plane.n, plane.d, halves);
        pieces = std::move(halves);
      }
      // Each convex piece as a fan from its first corner, or from its centre where crossings
      // end along its edges; the first triangle replaces t.
      std::vector<std::array<Bary, 3>> triangles;
      for (const auto& piece : pieces) {
        const std::vector<Bary> ring = withCrossingEnds(w, piece, planes);
        if (ring.size() == piece.size()) {
          for (std::size_t k = 1; k + 1 < piece.size(); ++k)
            triangles.push_back({piece[0], piece[k], piece[k + 1]});
          continue;
        }
        Bary centre{0, 0, 0};
        for (const Bary& b : piece)
          for (int c = 0; c < 3; ++c) centre[c] += b[c] / static_cast<double>(piece.size());
        for (std::size_t k = 0; k < ring.size(); ++k)
          triangles.push_back({centre, ring[k], ring[(k + 1) % ring.size()]});
      }
      if (triangles.size() > 1) ++result.cutTriangles;
      result.addedTriangles += triangles.size() - 1;
      // Vertices first: they interpolate t's original corners, which the first piece replaces.
      std::vector<std::array<uint32_t, 3>> vertices(triangles.size());
      for (std::size_t k = 0; k < triangles.size(); ++k)
        for (int c = 0; c < 3; ++c) vertices[k][c] = cutter.vertex(t, triangles[k][c], w);
      for (std::size_t k = 0; k < triangles.size(); ++k) {
        const std::array<uint32_t, 3>& v = vertices[k];
        uint8_t flags = 0;
        for (int c = 0; c < 3; ++c) {
          const glm::dvec3 a = at(w, triangles[k][c]), b = at(w, triangles[k][(c + 1) % 3]);
          for (const CrossingPlane& plane : planes) {
            if (std::abs(glm::dot(plane.n, a) - plane.d) > kOnPlane ||
                std::abs(glm::dot(plane.n, b) - plane.d) > kOnPlane)
              continue;
            flags |= static_cast<uint8_t>(1u << c);
            for (const uint32_t x : plane.crossers)
              if (onTriangle(tree.triangles()[x], 0.5 * (a + b)))
                flags |= static_cast<uint8_t>(1u << (c + 3));
          }
        }
        if (k == 0) {
          for (int c = 0; c < 3; ++c) mesh.indices[3 * t + c] = v[c];
          mesh.cutEdges[t] = flags;
        } else {
          mesh.indices.insert(mesh.indices.end(), v.begin(), v.end());
          mesh.cutEdges.push_back(flags);
        }
      }
    }
  }
  return result;
}

}  // namespace bounce
