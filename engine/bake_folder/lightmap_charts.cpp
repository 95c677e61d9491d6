#include "bake_folder/lightmap_charts.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace bounce {
namespace {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

uint64_t uvKey(glm::vec2 uv) {
  return (uint64_t{std::bit_cast<uint32_t>(uv.x)} << 32) | std::bit_cast<uint32_t>(uv.y);
}

// Does the triangle (in texel units) overlap the square [x, x+1] × [y, y+1]? Separating axes:
// the square's two axes and the triangle's three edge normals.
bool overlapsTexel(const glm::vec2 p[3], int x, int y) {
  const glm::vec2 lo(x, y), hi(x + 1, y + 1);
  for (int e = 0; e < 3; ++e) {
    const glm::vec2 a = p[e], b = p[(e + 1) % 3], c = p[(e + 2) % 3];
    const glm::vec2 n(a.y - b.y, b.x - a.x);  // normal of edge ab
    const float side = glm::dot(n, c - a);    // the triangle's side of the edge
    if (side == 0.0f) continue;               // degenerate: the box axes decide
    // The square's corner furthest towards the triangle's side.
    const glm::vec2 corner(((n.x > 0) == (side > 0)) ? hi.x : lo.x,
                           ((n.y > 0) == (side > 0)) ? hi.y : lo.y);
    if (glm::dot(n, corner - a) * side < 0.0f) return false;
  }
  return true;  // the box axes are handled by the caller's bounding-box loop
}

}  // namespace

LightmapCharts findCharts(const LightmapLayout& layout) {
  LightmapCharts charts;
  charts.triangleChart.resize(layout.instances.size());
  uint32_t next = 0;
  for (std::size_t r = 0; r < layout.instances.size(); ++r) {
    const std::vector<glm::vec2>& uv = layout.instances[r].cornerUv;
    const std::size_t triangles = uv.size() / 3;
    DisjointSets sets(triangles);
    // Undirected atlas edge (two UV keys, smaller first) → the first triangle seen with it.
    std::map<std::pair<uint64_t, uint64_t>, std::size_t> firstOwner;
    for (std::size_t t = 0; t < triangles; ++t)
      for (int c = 0; c < 3; ++c) {
        const uint64_t a = uvKey(uv[3 * t + c]), b = uvKey(uv[3 * t + (c + 1) % 3]);
        const auto [it, inserted] = firstOwner.try_emplace(std::minmax(a, b), t);
        if (!inserted) sets.join(it->second, t);
      }
    std::vector<uint32_t>& chartOf = charts.triangleChart[r];
    chartOf.resize(triangles);
    std::map<std::size_t, uint32_t> number;  // root → chart, in order of first triangle
    for (std::size_t t = 0; t < triangles; ++t) {
      const auto [it, inserted] = number.try_emplace(sets.find(t), next);
      if (inserted) ++next;
      chartOf[t] = it->second;
    }
  }
  charts.count = static_cast<int>(next);
  return charts;
}

glm::vec3 chartColour(uint32_t chart) {
  // Hues spaced by the golden angle; saturation and value alternate so neighbours differ.
  const float h = std::fmod(static_cast<float>(chart) * 0.618034f, 1.0f) * 6.0f;
  const float s = chart % 2 ? 0.55f : 0.85f;
  const float v = chart % 3 == 0 ? 0.95f : 0.75f;
  const float f = h - std::floor(h);
  const float p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (static_cast<int>(h) % 6) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

std::vector<int32_t> chartIdImage(const LightmapLayout& layout, const LightmapCharts& charts) {
  const int width = std::max(layout.width, 0), height = std::max(layout.height, 0);
  std::vector<int32_t> ids(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
  const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
  for (std::size_t r = 0; r < layout.instances.size(); ++r) {
    const std::vector<glm::vec2>& uv = layout.instances[r].cornerUv;
    for (std::size_t t = 0; t < uv.size() / 3; ++t) {
      const glm::vec2 p[3] = {uv[3 * t] * size, uv[3 * t + 1] * size, uv[3 * t + 2] * size};
      const glm::vec2 lo = glm::min(p[0], glm::min(p[1], p[2]));
      const glm::vec2 hi = glm::max(p[0], glm::max(p[1], p[2]));
      const int x0 = std::max(static_cast<int>(std::floor(lo.x)), 0);
      const int y0 = std::max(static_cast<int>(std::floor(lo.y)), 0);
      const int x1 = std::min(static_cast<int>(std::floor(hi.x)), width - 1);
      const int y1 = std::min(static_cast<int>(std::floor(hi.y)), height - 1);
      const auto chart = static_cast<int32_t>(charts.triangleChart[r][t]);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
          if (overlapsTexel(p, x, y))
            ids[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)] = chart;
    }
  }
  return ids;
}

Image chartImage(const LightmapLayout& layout, const LightmapCharts& charts) {
  Image image(std::max(layout.width, 0), std::max(layout.height, 0));
  const std::vector<int32_t> ids = chartIdImage(layout, charts);
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] >= 0) image.pixels[i] = chartColour(static_cast<uint32_t>(ids[i]));
  return image;
}

}  // namespace bounce
