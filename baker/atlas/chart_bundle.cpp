#include "atlas/chart_bundle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace bounce {
namespace {

// Gap between two pieces of a bundle, in texels: keeps their triangles apart despite rounding.
constexpr float kPieceGap = 0.01f;

glm::vec2 extentOf(const Chart& chart) {
  glm::vec2 hi(0.0f);
  for (const glm::vec2 p : chart.cornerUv) hi = glm::max(hi, p);
  return hi;
}

// (cube x, y, z, facing): which bundle a sub-texel chart joins; facing is 2 × axis + (sign < 0).
std::array<int64_t, 4> bundleKey(const WorldMesh& mesh, const Chart& chart, double texelSize) {
  glm::dvec3 normal(0.0), centre(0.0);
  double weight = 0.0;
  for (const uint32_t t : chart.triangles) {
    const glm::dvec3 a(mesh.corner(t, 0)), b(mesh.corner(t, 1)), c(mesh.corner(t, 2));
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double area = glm::length(cross);
    normal += cross;
    centre += (a + b + c) * (area / 3.0);
    weight += area;
  }
  centre = weight > 0.0 ? centre / weight : glm::dvec3(mesh.corner(chart.triangles[0], 0));
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  const glm::dvec3 cube = glm::floor(centre / texelSize);
  return {static_cast<int64_t>(cube.x), static_cast<int64_t>(cube.y), static_cast<int64_t>(cube.z),
          2 * axis + (normal[axis] < 0.0 ? 1 : 0)};
}

// Lays the pieces side by side in rows (tallest first, ties by order) and returns one chart.
Chart bundle(const std::vector<Chart>& charts, const std::vector<std::size_t>& pieces,
             float texelSize) {
  std::vector<glm::vec2> extent;
  float area = 0.0f, widest = 0.0f;
  for (const std::size_t c : pieces) {
    extent.push_back(extentOf(charts[c]));
    area += extent.back().x * extent.back().y;
    widest = std::max(widest, extent.back().x);
  }
  std::vector<std::size_t> order(pieces.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return extent[a].y > extent[b].y; });
  const float gap = kPieceGap * texelSize;
  const float rowWidth = std::max(widest, std::sqrt(area));
  Chart out{charts[pieces[0]].instance, {}, {}, ChartSource::Bundle};
  glm::vec2 cursor(0.0f);
  float rowHeight = 0.0f;
  for (const std::size_t k : order) {
    if (cursor.x > 0.0f && cursor.x + extent[k].x > rowWidth) {
      cursor = glm::vec2(0.0f, cursor.y + rowHeight + gap);
      rowHeight = 0.0f;
    }
    const Chart& piece = charts[pieces[k]];
    out.triangles.insert(out.triangles.end(), piece.triangles.begin(), piece.triangles.end());
    for (const glm::vec2 p : piece.cornerUv) out.cornerUv.push_back(p + cursor);
    cursor.x += extent[k].x + gap;
    rowHeight = std::max(rowHeight, extent[k].y);
  }
  return out;
}

}  // namespace

std::vector<Chart> bundleSubTexelCharts(const WorldMesh& mesh, std::vector<Chart> charts,
                                        float texelSize) {
  std::map<std::array<int64_t, 4>, std::vector<std::size_t>> groups;
  std::vector<const std::vector<std::size_t>*> groupOf(charts.size(), nullptr);
  for (std::size_t c = 0; c < charts.size(); ++c) {
    const Chart& chart = charts[c];
    if (chart.source == ChartSource::Degenerate || chart.triangles.empty()) continue;
    const glm::vec2 extent = extentOf(chart);
    if (extent.x > texelSize || extent.y > texelSize) continue;
    std::vector<std::size_t>& group = groups[bundleKey(mesh, chart, texelSize)];
    group.push_back(c);
    groupOf[c] = &group;
  }
  std::vector<Chart> out;
  for (std::size_t c = 0; c < charts.size(); ++c) {
    const std::vector<std::size_t>* group = groupOf[c];
    if (!group || group->size() == 1)
      out.push_back(std::move(charts[c]));
    else if (group->front() == c)
      out.push_back(bundle(charts, *group, texelSize));
  }
  return out;
}

}  // namespace bounce
