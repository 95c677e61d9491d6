// 2D geometry of atlas triangles, in texel units (texel (x, y) is the square [x, x+1] × [y, y+1]).
// Shared by the atlas (coverage, validation of charts and of a mesh's own uv1), the baker (which
// texels a triangle touches) and the tests.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

// A triangle touches a texel when it overlaps the texel's square shrunk by this many texels on
// every side: touching along an edge or a corner, or overhanging by float round-off, does not
// count. Conservative otherwise: a sliver crossing a texel's corner counts.
inline constexpr float kCoverageEpsilon = 1e-3f;

// Signed area (counter-clockwise in a y-up frame positive), in the units of the points squared.
inline float signedArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return 0.5f * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// True when triangle abc overlaps the box [lo, hi] by more than zero (separating-axis test on
// the two box axes and the three edge normals; touching is not overlapping).
bool triangleOverlapsBox(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 lo, glm::vec2 hi);

// True when the interiors of two triangles overlap by more than `tolerance` (in their units)
// along every separating axis: triangles sharing an edge or a vertex do not overlap.
bool trianglesOverlap(const glm::vec2* t0, const glm::vec2* t1, float tolerance);

// Calls visit(x, y) for every texel of a width × height grid that triangle abc (texel units)
// touches (see kCoverageEpsilon). Texels outside the grid are skipped.
template <class Visit>
void forEachTouchedTexel(glm::vec2 a, glm::vec2 b, glm::vec2 c, int width, int height,
                         Visit&& visit) {
  const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
  const int x0 = std::max(0, static_cast<int>(glm::floor(lo.x)));
  const int y0 = std::max(0, static_cast<int>(glm::floor(lo.y)));
  const int x1 = std::min(width - 1, static_cast<int>(glm::floor(hi.x)));
  const int y1 = std::min(height - 1, static_cast<int>(glm::floor(hi.y)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::vec2 cell(static_cast<float>(x), static_cast<float>(y));
      if (triangleOverlapsBox(a, b, c, cell + kCoverageEpsilon, cell + (1.0f - kCoverageEpsilon)))
        visit(x, y);
    }
}

// The part of triangle abc inside the square [lo, hi]: a convex polygon of up to 7 corners, in
// the triangle's winding, empty when they do not overlap (Sutherland–Hodgman clipping). What the
// baker samples for a texel the triangle touches; its area is the texel's share of the triangle.
std::vector<glm::vec2> clipTriangleToBox(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 lo,
                                         glm::vec2 hi);

// Area of a simple polygon (absolute value), in the units of its points squared.
float polygonArea(const std::vector<glm::vec2>& polygon);

// The first pair of triangles (indices into the list, 3 corners each) whose interiors overlap
// by more than `tolerance`, or nothing. A uniform grid keeps it near-linear.
std::optional<std::pair<uint32_t, uint32_t>> findOverlappingTriangles(
    const std::vector<glm::vec2>& cornerUv, float tolerance);

// Convex hull of the points, counter-clockwise, no collinear points (Andrew's monotone chain).
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points);

}  // namespace bounce
