#include "atlas/chart_flatten.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Sparse>

#include "atlas/uv_geometry.h"

namespace bounce {
namespace {

glm::dvec3 crossOf(const WorldMesh& mesh, uint32_t t) {
  const glm::dvec3 a(mesh.corner(t, 0)), b(mesh.corner(t, 1)), c(mesh.corner(t, 2));
  return glm::cross(b - a, c - a);
}

// Every triangle keeps the orientation of the chart (positive area) and none overlaps another.
bool acceptable(const std::vector<glm::vec2>& uv) {
  for (std::size_t t = 0; t < uv.size(); t += 3)
    if (!(signedArea(uv[t], uv[t + 1], uv[t + 2]) > 0.0f)) return false;
  return !findOverlappingTriangles(uv, 1e-4f).has_value();
}

}  // namespace

FlatChart flattenPlanar(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                        float texelSize) {
  glm::dvec3 sum(0.0);
  for (const uint32_t t : triangles) sum += crossOf(mesh, t);
  const glm::dvec3 n = glm::normalize(sum);
  // An orthonormal basis (s, t, n), right-handed, so counter-clockwise stays positive.
  const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 s = glm::normalize(glm::cross(helper, n));
  const glm::dvec3 t = glm::cross(n, s);
  const glm::dvec3 origin(mesh.corner(triangles[0], 0));
  const double scale = 1.0 / static_cast<double>(texelSize);
  FlatChart flat;
  flat.source = ChartSource::Planar;
  for (const uint32_t tri : triangles)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 d = glm::dvec3(mesh.corner(tri, k)) - origin;
      flat.cornerUv.emplace_back(static_cast<float>(glm::dot(d, s) * scale),
                                 static_cast<float>(glm::dot(d, t) * scale));
    }
  if (!acceptable(flat.cornerUv)) flat.cornerUv.clear();
  return flat;
}

FlatChart flattenConformal(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                           float texelSize) {
  // Chart vertices: corners welded by position (the segmentation's connectivity).
  std::map<std::array<float, 3>, int> index;
  std::vector<int> cornerVertex;
  for (const uint32_t tri : triangles)
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = mesh.corner(tri, k);
      const auto [it, added] = index.try_emplace({p.x, p.y, p.z}, static_cast<int>(index.size()));
      cornerVertex.push_back(it->second);
    }
  return flattenConformal(mesh, triangles, cornerVertex, texelSize);
}

FlatChart flattenConformal(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                           const std::vector<int>& cornerVertex, float texelSize) {
  int n = 0;
  for (const int v : cornerVertex) n = std::max(n, v + 1);
  std::vector<glm::dvec3> vertex(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < cornerVertex.size(); ++k)
    vertex[cornerVertex[k]] = glm::dvec3(mesh.corner(triangles[k / 3], static_cast<int>(k % 3)));
  FlatChart flat;
  flat.source = ChartSource::Conformal;
  if (n < 3) return flat;

  // Pins: the two vertices roughly farthest apart, at their 3D distance.
  auto farthestFrom = [&](int from) {
    int best = from;
    double bestDistance = -1.0;
    for (int v = 0; v < n; ++v) {
      const double d = glm::distance(vertex[v], vertex[from]);
      if (d > bestDistance) bestDistance = d, best = v;
    }
    return best;
  };
  const int pinA = farthestFrom(0), pinB = farthestFrom(pinA);
  const double pinDistance = glm::distance(vertex[pinA], vertex[pinB]);
  if (pinA == pinB || !(pinDistance > 0.0)) return flat;
  // Unknowns: u then v of every unpinned vertex.
  std::vector<int> column(n, -1);
  int free = 0;
  for (int v = 0; v < n; ++v)
    if (v != pinA && v != pinB) column[v] = free++;
  auto pinnedUv = [&](int v) { return v == pinA ? glm::dvec2(0.0) : glm::dvec2(pinDistance, 0.0); };

  // Per triangle, two residuals of the Cauchy-Riemann equations of the map from the triangle's
  // own orthonormal frame to (u, v): ∂u/∂x − ∂v/∂y and ∂u/∂y + ∂v/∂x, weighted by √area.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const glm::dvec3 p0 = vertex[cornerVertex[3 * t]], p1 = vertex[cornerVertex[3 * t + 1]],
                     p2 = vertex[cornerVertex[3 * t + 2]];
    const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
    const glm::dvec3 x = glm::normalize(e1);
    const glm::dvec3 y = glm::normalize(glm::cross(glm::cross(e1, e2), e1));
    const glm::dvec2 q[3] = {
        {0.0, 0.0}, {glm::length(e1), 0.0}, {glm::dot(e2, x), glm::dot(e2, y)}};
    const double area = 0.5 * q[1].x * q[2].y;
    if (!(area > 0.0)) return flat;
    const double weight = std::sqrt(area);
    const auto row = static_cast<int>(2 * t);
    for (int j = 0; j < 3; ++j) {
      // ∇ of the hat function of corner j: the opposite edge turned by +90°, over 2·area.
      const glm::dvec2 e = q[(j + 2) % 3] - q[(j + 1) % 3];
      const glm::dvec2 g = glm::dvec2(-e.y, e.x) / (2.0 * area) * weight;
      const int v = cornerVertex[3 * t + j];
      if (column[v] >= 0) {
        entries.emplace_back(row, column[v], g.x);
        entries.emplace_back(row, free + column[v], -g.y);
        entries.emplace_back(row + 1, column[v], g.y);
        entries.emplace_back(row + 1, free + column[v], g.x);
      } else {
        const glm::dvec2 uv = pinnedUv(v);
        rhs[row] -= g.x * uv.x - g.y * uv.y;
        rhs[row + 1] -= g.y * uv.x + g.x * uv.y;
      }
    }
  }
  Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(2 * triangles.size()), 2 * free);
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> normal = a.transpose() * a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return flat;
  const Eigen::VectorXd solution = solver.solve(a.transpose() * rhs);
  if (solver.info() != Eigen::Success) return flat;

  std::vector<glm::dvec2> uv(n);
  for (int v = 0; v < n; ++v)
    uv[v] =
        column[v] < 0 ? pinnedUv(v) : glm::dvec2(solution[column[v]], solution[free + column[v]]);
  // One texel density on the whole chart: UV area / world area = 1/texelSize².
  double uvArea = 0.0, worldArea = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const glm::dvec2 a0 = uv[cornerVertex[3 * t]], a1 = uv[cornerVertex[3 * t + 1]],
                     a2 = uv[cornerVertex[3 * t + 2]];
    uvArea += 0.5 * ((a1.x - a0.x) * (a2.y - a0.y) - (a2.x - a0.x) * (a1.y - a0.y));
    worldArea += 0.5 * glm::length(crossOf(mesh, triangles[t]));
  }
  if (!(uvArea > 0.0) || !std::isfinite(uvArea)) return flat;
  const double scale = std::sqrt(worldArea / uvArea) / static_cast<double>(texelSize);
  for (const int v : cornerVertex) flat.cornerUv.emplace_back(glm::vec2(uv[v] * scale));
  if (!acceptable(flat.cornerUv)) flat.cornerUv.clear();
  return flat;
}

FlatChart flattenChart(const WorldMesh& mesh, const std::vector<uint32_t>& triangles,
                       float texelSize) {
  glm::dvec3 sum(0.0);
  for (const uint32_t t : triangles) sum += crossOf(mesh, t);
  const glm::dvec3 mean = glm::normalize(sum);
  bool planar = true;
  const double cosPlanar = std::cos(static_cast<double>(kPlanarAngle));
  for (const uint32_t t : triangles)
    planar = planar && glm::dot(glm::normalize(crossOf(mesh, t)), mean) >= cosPlanar;
  if (planar) {
    FlatChart flat = flattenPlanar(mesh, triangles, texelSize);
    if (!flat.cornerUv.empty()) return flat;
  }
  FlatChart flat = flattenConformal(mesh, triangles, texelSize);
  if (!flat.cornerUv.empty()) return flat;
  return flattenPlanar(mesh, triangles, texelSize);
}

void orientChart(std::vector<glm::vec2>& cornerUv) {
  if (cornerUv.empty()) return;
  const std::vector<glm::vec2> hull = convexHull(cornerUv);
  float bestArea = INFINITY, bestAngle = 0.0f;
  for (std::size_t i = 0; i < hull.size() && hull.size() >= 3; ++i) {
    const glm::vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    const float angle = std::atan2(e.y, e.x);
    const float c = std::cos(angle), s = std::sin(angle);
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec2 p : hull) {
      const glm::vec2 r(c * p.x + s * p.y, -s * p.x + c * p.y);
      lo = glm::min(lo, r);
      hi = glm::max(hi, r);
    }
    const float area = (hi.x - lo.x) * (hi.y - lo.y);
    if (area < bestArea * (1.0f - 1e-5f)) bestArea = area, bestAngle = angle;
  }
  const float c = std::cos(bestAngle), s = std::sin(bestAngle);
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (glm::vec2& p : cornerUv) {
    p = glm::vec2(c * p.x + s * p.y, -s * p.x + c * p.y);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const bool turn = hi.y - lo.y > hi.x - lo.x;  // a quarter turn makes it landscape
  for (glm::vec2& p : cornerUv) {
    const glm::vec2 d = p - lo;
    p = turn ? glm::vec2(hi.y - lo.y - d.y, d.x) : d;
  }
}

}  // namespace bounce
