#include "scene/area_light_outline.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <span>

namespace bounce {

namespace {

// Corners compared exactly: triangles of one mesh share their corners bit for bit, and a loop
// that does not close by exact corners falls back to the triangles (still exact, only slower).
struct CornerLess {
  bool operator()(const glm::vec3& a, const glm::vec3& b) const {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
  }
};

struct EdgeLess {
  bool operator()(const std::pair<glm::vec3, glm::vec3>& a,
                  const std::pair<glm::vec3, glm::vec3>& b) const {
    const CornerLess less;
    if (less(a.first, b.first)) return true;
    if (less(b.first, a.first)) return false;
    return less(a.second, b.second);
  }
};

bool samePlane(std::span<const EmitterTriangle> triangles, const AreaLight& light) {
  if (glm::dot(light.normal, light.normal) == 0.0f) return false;
  const float tolerance = 1e-5f * std::max(light.radius, 1e-3f);
  const EmitterTriangle& first = triangles.front();
  for (const EmitterTriangle& t : triangles) {
    if (t.radiance != first.radiance || t.doubleSided != first.doubleSided) return false;
    const glm::vec3 c = glm::cross(t.v1 - t.v0, t.v2 - t.v0);
    const float length = glm::length(c);
    if (length == 0.0f || glm::dot(c / length, light.normal) < 0.99999f) return false;
    for (const glm::vec3& v : {t.v0, t.v1, t.v2})
      if (std::abs(glm::dot(light.normal, v - light.centre)) > tolerance) return false;
  }
  return true;
}

}  // namespace

std::optional<std::vector<glm::vec3>> areaLightOutline(const AreaLightSet& set,
                                                       const AreaLight& light,
                                                       std::size_t maxCorners) {
  if (light.count == 0) return std::nullopt;
  const std::span<const EmitterTriangle> triangles(set.triangles.data() + light.first, light.count);
  if (!samePlane(triangles, light)) return std::nullopt;
  // Directed edges (counter-clockwise about the front normal); an edge walked both ways is
  // interior and cancels. What is left is the boundary: each corner must start exactly one.
  std::map<std::pair<glm::vec3, glm::vec3>, int, EdgeLess> edges;
  for (const EmitterTriangle& t : triangles) {
    const glm::vec3 v[3] = {t.v0, t.v1, t.v2};
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 a = v[k], b = v[(k + 1) % 3];
      if (auto back = edges.find({b, a}); back != edges.end()) {
        if (--back->second == 0) edges.erase(back);
      } else if (++edges[{a, b}] > 1) {
        return std::nullopt;  // two triangles over one another
      }
    }
  }
  std::map<glm::vec3, glm::vec3, CornerLess> next;
  for (const auto& [edge, count] : edges)
    if (!next.emplace(edge.first, edge.second).second) return std::nullopt;  // a pinch corner
  if (next.size() < 3) return std::nullopt;
  std::vector<glm::vec3> loop{next.begin()->first};
  for (glm::vec3 at = next.begin()->second; !(at == loop.front());) {
    const auto step = next.find(at);
    if (step == next.end() || loop.size() > next.size()) return std::nullopt;  // an open chain
    loop.push_back(at);
    at = step->second;
  }
  if (loop.size() != next.size()) return std::nullopt;  // more than one loop: a hole or pieces
  // Drop corners where the outline runs straight on (a panel cut into strips).
  std::vector<glm::vec3> corners;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::vec3 a = loop[(i + loop.size() - 1) % loop.size()], b = loop[i],
                    c = loop[(i + 1) % loop.size()];
    const glm::vec3 turn = glm::cross(b - a, c - b);
    if (glm::length(turn) > 1e-6f * glm::length(b - a) * glm::length(c - b)) corners.push_back(b);
  }
  if (corners.size() < 3 || corners.size() > maxCorners) return std::nullopt;
  return corners;
}

}  // namespace bounce
