#include "render/light_grid.h"

#include <algorithm>
#include <cmath>

namespace bounce {
namespace {

float squaredDistance(const Box& a, const Box& b) {
  const glm::vec3 gap = glm::max(glm::vec3(0.0f), glm::max(a.lower - b.upper, b.lower - a.upper));
  return glm::dot(gap, gap);
}

// The cone (apex, unit axis, half-angle) misses the sphere (c, r) when the sphere lies wholly
// outside the cone's side: the distance from c to the cone's surface, cosθ·|v⊥| − sinθ·v∥ with
// v = c − apex split along the axis, exceeds r; or wholly behind the apex (v∥ < −r). A cone wider
// than a half-space (θ ≥ 90°) never misses by its side.
bool coneMissesSphere(const LightReach& cone, glm::vec3 c, float r) {
  const glm::vec3 v = c - cone.centre;
  const float along = glm::dot(v, cone.axis);
  if (along < -r) return true;
  if (cone.cosOuter <= 0.0f) return false;
  const float across = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0f));
  return cone.cosOuter * across - cone.sinOuter * along > r;
}

struct TileRange {
  int x0, x1, y0, y1, s0, s1;  // inclusive
  bool empty() const { return x0 > x1 || y0 > y1 || s0 > s1; }
};

// The clusters the view-space box `b` may overlap: its depth range's slices, and the tiles its
// corners project to (all tiles when it reaches the camera's plane).
TileRange clusterRange(const ClusterGrid& grid, const Box& b) {
  const float dMin = -b.upper.z, dMax = -b.lower.z;
  if (dMax < grid.nearDepth * (1.0f - 1e-4f) || dMin > grid.farDepth * (1.0f + 1e-4f))
    return {0, -1, 0, -1, 0, -1};
  TileRange range{0,
                  grid.tilesX - 1,
                  0,
                  grid.tilesY - 1,
                  grid.sliceOf(std::max(dMin, grid.nearDepth)),
                  grid.sliceOf(std::min(dMax, grid.farDepth))};
  // A slice boundary computed in float may round either way: take the neighbours too.
  range.s0 = std::max(range.s0 - 1, 0);
  range.s1 = std::min(range.s1 + 1, grid.slices - 1);
  if (dMin <= 1e-6f) return range;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 p((k & 1) ? b.upper.x : b.lower.x, (k & 2) ? b.upper.y : b.lower.y,
                      (k & 4) ? b.upper.z : b.lower.z);
    const glm::vec2 slope = glm::vec2(p.x, p.y) / (-p.z);
    lo = glm::min(lo, slope);
    hi = glm::max(hi, slope);
  }
  // view x/d → pixel: (x/d / tanHalf + 1) / 2 · size; then tiles, one more on each side.
  const auto tile = [&](float slope, float tanHalf, int size, int tiles) {
    const float pixel = (slope / tanHalf + 1.0f) * 0.5f * static_cast<float>(size);
    const float t = std::floor(pixel / static_cast<float>(grid.tilePixels));
    return static_cast<int>(std::clamp(t, -1.0f, static_cast<float>(tiles)));
  };
  range.x0 = std::max(tile(lo.x, grid.tanHalfFov.x, grid.width, grid.tilesX) - 1, 0);
  range.x1 = std::min(tile(hi.x, grid.tanHalfFov.x, grid.width, grid.tilesX) + 1, grid.tilesX - 1);
  range.y0 = std::max(tile(lo.y, grid.tanHalfFov.y, grid.height, grid.tilesY) - 1, 0);
  range.y1 = std::min(tile(hi.y, grid.tanHalfFov.y, grid.height, grid.tilesY) + 1, grid.tilesY - 1);
  return range;
}

Box reachBox(const LightReach& reach) {
  if (reach.shape == LightReach::Shape::Box)
    return {reach.box.lower - glm::vec3(reach.radius), reach.box.upper + glm::vec3(reach.radius)};
  return {reach.centre - glm::vec3(reach.radius), reach.centre + glm::vec3(reach.radius)};
}

// Appends (cluster, light) for every cluster `reach` (view space) may touch; `boxes[c]` is
// cluster c's grid.clusterBox.
void collect(const ClusterGrid& grid, std::span<const Box> boxes, const LightReach& reach,
             uint32_t light, std::vector<glm::uvec2>& hits) {
  if (reach.shape == LightReach::Shape::None) return;
  if (reach.shape == LightReach::Shape::Everywhere) {
    for (int c = 0; c < grid.count(); ++c) hits.emplace_back(c, light);
    return;
  }
  const TileRange range = clusterRange(grid, reachBox(reach));
  if (range.empty()) return;
  for (int s = range.s0; s <= range.s1; ++s)
    for (int y = range.y0; y <= range.y1; ++y)
      for (int x = range.x0; x <= range.x1; ++x)
        if (const int c = grid.index(x, y, s); reachTouches(reach, boxes[c]))
          hits.emplace_back(c, light);
}

}  // namespace

bool reachTouches(const LightReach& reach, const Box& cluster) {
  switch (reach.shape) {
    case LightReach::Shape::None:
      return false;
    case LightReach::Shape::Everywhere:
      return true;
    case LightReach::Shape::Box:
      return squaredDistance(reach.box, cluster) <= reach.radius * reach.radius;
    case LightReach::Shape::Sphere:
    case LightReach::Shape::Cone: {
      const Box point{reach.centre, reach.centre};
      if (squaredDistance(point, cluster) > reach.radius * reach.radius) return false;
      if (reach.shape == LightReach::Shape::Sphere) return true;
      // The cluster's bounding sphere against the cone.
      const glm::vec3 c = 0.5f * (cluster.lower + cluster.upper);
      return !coneMissesSphere(reach, c, 0.5f * glm::length(cluster.upper - cluster.lower));
    }
  }
  return true;
}

LightReach toView(const LightReach& reach, const glm::mat4& view) {
  LightReach out = reach;
  out.centre = glm::vec3(view * glm::vec4(reach.centre, 1.0f));
  out.axis = glm::normalize(glm::mat3(view) * reach.axis);
  if (reach.shape == LightReach::Shape::Box) out.box = transformBox(reach.box, view);
  return out;
}

LightGridLists assignLights(const ClusterGrid& grid, std::span<const LightReach> punctual,
                            std::span<const LightReach> area,
                            std::span<const uint32_t> punctualOrder) {
  const auto clusters = static_cast<std::size_t>(grid.count());
  // Each cluster's box once (two slice depths each), not once per light that may reach it.
  std::vector<Box> boxes(clusters);
  for (int s = 0; s < grid.slices; ++s)
    for (int y = 0; y < grid.tilesY; ++y)
      for (int x = 0; x < grid.tilesX; ++x) boxes[grid.index(x, y, s)] = grid.clusterBox(x, y, s);
  std::vector<glm::uvec2> punctualHits, areaHits;  // (cluster, light)
  for (std::size_t k = 0; k < punctual.size(); ++k) {
    const uint32_t i = k < punctualOrder.size() ? punctualOrder[k] : static_cast<uint32_t>(k);
    collect(grid, boxes, toView(punctual[i], grid.view), i, punctualHits);
  }
  for (std::size_t i = 0; i < area.size(); ++i)
    collect(grid, boxes, toView(area[i], grid.view), static_cast<uint32_t>(i), areaHits);

  // Counting sort by cluster (stable): each list follows the order the lights were visited in.
  std::vector<uint32_t> punctualCount(clusters, 0), areaCount(clusters, 0);
  for (const glm::uvec2& h : punctualHits) ++punctualCount[h.x];
  for (const glm::uvec2& h : areaHits) ++areaCount[h.x];
  std::vector<std::size_t> first(clusters + 1, 0);
  for (std::size_t c = 0; c < clusters; ++c)
    first[c + 1] = first[c] + punctualCount[c] + areaCount[c];
  std::vector<float> entries(first[clusters], 0.0f);
  std::vector<std::size_t> nextPunctual(first.begin(), first.end() - 1), nextArea(clusters);
  for (std::size_t c = 0; c < clusters; ++c) nextArea[c] = first[c] + punctualCount[c];
  for (const glm::uvec2& h : punctualHits) entries[nextPunctual[h.x]++] = static_cast<float>(h.y);
  for (const glm::uvec2& h : areaHits) entries[nextArea[h.x]++] = static_cast<float>(h.y);

  LightGridLists lists;
  lists.headers.reserve(clusters);
  for (std::size_t c = 0; c < clusters; ++c) {
    lists.headers.emplace_back(static_cast<float>(first[c]), static_cast<float>(punctualCount[c]),
                               static_cast<float>(areaCount[c]), 0.0f);
    lists.maxPunctual = std::max<std::size_t>(lists.maxPunctual, punctualCount[c]);
    lists.maxArea = std::max<std::size_t>(lists.maxArea, areaCount[c]);
  }
  lists.entries.resize((entries.size() + 3) / 4, glm::vec4(0.0f));
  for (std::size_t k = 0; k < entries.size(); ++k) lists.entries[k / 4][k % 4] = entries[k];
  lists.punctualEntries = punctualHits.size();
  lists.areaEntries = areaHits.size();
  return lists;
}

}  // namespace bounce
