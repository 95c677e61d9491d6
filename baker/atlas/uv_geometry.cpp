#include "atlas/uv_geometry.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace bounce {
namespace {

// Projection interval of `count` points on `axis`.
std::pair<float, float> project(const glm::vec2* points, int count, glm::vec2 axis) {
  float lo = glm::dot(points[0], axis), hi = lo;
  for (int i = 1; i < count; ++i) {
    const float d = glm::dot(points[i], axis);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

// True when the two point sets are separated along `axis` (overlap ≤ tolerance × |axis|).
bool separated(const glm::vec2* p, int np, const glm::vec2* q, int nq, glm::vec2 axis,
               float tolerance) {
  const float len = glm::length(axis);
  if (len == 0.0f) return false;
  const auto [plo, phi] = project(p, np, axis);
  const auto [qlo, qhi] = project(q, nq, axis);
  return std::min(phi, qhi) - std::max(plo, qlo) <= tolerance * len;
}

glm::vec2 edgeNormal(glm::vec2 a, glm::vec2 b) {
  return glm::vec2(a.y - b.y, b.x - a.x);
}

}  // namespace

bool triangleOverlapsBox(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 lo, glm::vec2 hi) {
  const glm::vec2 tri[3] = {a, b, c};
  const glm::vec2 box[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  if (separated(tri, 3, box, 4, {1, 0}, 0.0f) || separated(tri, 3, box, 4, {0, 1}, 0.0f))
    return false;
  for (int e = 0; e < 3; ++e)
    if (separated(tri, 3, box, 4, edgeNormal(tri[e], tri[(e + 1) % 3]), 0.0f)) return false;
  return true;
}

bool trianglesOverlap(const glm::vec2* t0, const glm::vec2* t1, float tolerance) {
  for (const glm::vec2* t : {t0, t1})
    for (int e = 0; e < 3; ++e)
      if (separated(t0, 3, t1, 3, edgeNormal(t[e], t[(e + 1) % 3]), tolerance)) return false;
  // Degenerate triangles (all edge normals zero) are never reported as overlapping.
  return std::abs(signedArea(t0[0], t0[1], t0[2])) > 0.0f &&
         std::abs(signedArea(t1[0], t1[1], t1[2])) > 0.0f;
}

std::optional<std::pair<uint32_t, uint32_t>> findOverlappingTriangles(
    const std::vector<glm::vec2>& cornerUv, float tolerance) {
  const auto triangles = static_cast<uint32_t>(cornerUv.size() / 3);
  if (triangles < 2) return std::nullopt;
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec2& p : cornerUv) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // About one triangle per cell on average.
  const glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-20f));
  const float cellsPerSide = std::ceil(std::sqrt(static_cast<float>(triangles)));
  const float cell = std::max(extent.x, extent.y) / cellsPerSide;
  const int nx = std::max(1, static_cast<int>(std::ceil(extent.x / cell)));
  const int ny = std::max(1, static_cast<int>(std::ceil(extent.y / cell)));
  std::vector<std::vector<uint32_t>> grid(static_cast<std::size_t>(nx) * ny);
  auto cellOf = [&](float v, float origin, int n) {
    return std::clamp(static_cast<int>((v - origin) / cell), 0, n - 1);
  };
  for (uint32_t t = 0; t < triangles; ++t) {
    const glm::vec2* p = &cornerUv[3 * t];
    const glm::vec2 tlo = glm::min(p[0], glm::min(p[1], p[2]));
    const glm::vec2 thi = glm::max(p[0], glm::max(p[1], p[2]));
    const int x0 = cellOf(tlo.x, lo.x, nx), x1 = cellOf(thi.x, lo.x, nx);
    const int y0 = cellOf(tlo.y, lo.y, ny), y1 = cellOf(thi.y, lo.y, ny);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        std::vector<uint32_t>& bucket = grid[static_cast<std::size_t>(y) * nx + x];
        for (const uint32_t other : bucket)
          if (trianglesOverlap(&cornerUv[3 * other], p, tolerance)) return std::make_pair(other, t);
        bucket.push_back(t);
      }
  }
  return std::nullopt;
}

std::vector<glm::vec2> clipTriangleToBox(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 lo,
                                         glm::vec2 hi) {
  std::vector<glm::vec2> polygon = {a, b, c}, clipped;
  // Keeps the side of the line coordinate[axis] = bound where sign·(p[axis] − bound) ≥ 0.
  auto clip = [&](int axis, float bound, float sign) {
    clipped.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::vec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
      const float dp = sign * (p[axis] - bound), dq = sign * (q[axis] - bound);
      if (dp >= 0.0f) clipped.push_back(p);
      if ((dp >= 0.0f) != (dq >= 0.0f)) clipped.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    polygon.swap(clipped);
  };
  clip(0, lo.x, 1.0f);
  if (!polygon.empty()) clip(0, hi.x, -1.0f);
  if (!polygon.empty()) clip(1, lo.y, 1.0f);
  if (!polygon.empty()) clip(1, hi.y, -1.0f);
  if (polygon.size() < 3) polygon.clear();
  return polygon;
}

float polygonArea(const std::vector<glm::vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 p(polygon[i]), q(polygon[(i + 1) % polygon.size()]);
    twice += p.x * q.y - q.x * p.y;
  }
  return static_cast<float>(0.5 * std::abs(twice));
}

std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points) {
  std::sort(points.begin(), points.end(),
            [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<glm::vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && signedArea(hull[k - 2], hull[k - 1], points[i]) <= 0.0f) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && signedArea(hull[k - 2], hull[k - 1], points[i]) <= 0.0f) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace bounce
