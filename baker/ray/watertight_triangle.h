// Watertight ray/triangle intersection (Woop, Benthin, Wald: "Watertight Ray/Triangle
// Intersection", JCGT 2013). The ray is sheared so that it runs along +z through the origin;
// the triangle's three 2D edge functions are then evaluated with the same operations for an
// edge seen from either of its triangles, so a ray through a shared edge or vertex can never
// fall between two triangles. Edge functions that round to exactly zero are re-evaluated in
// double, which settles the sign on edges; a triangle of zero area (all three edge functions
// summing to zero) never hits.
#pragma once

#include <cmath>
#include <utility>

#include <glm/glm.hpp>

#include "ray/ray_kernel.h"

namespace bounce {

// Per-ray constants of the shear: kz is the dominant direction axis. Coordinates are indexed
// through plain float arrays: glm's operator[] is a switch, costly with a run-time index.
struct ShearedRay {
  float origin[3];
  int kx, ky, kz;
  float sx, sy, sz;

  explicit ShearedRay(const Ray& ray) : origin{ray.origin.x, ray.origin.y, ray.origin.z} {
    const float d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    const glm::vec3 a = glm::abs(ray.direction);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = kz == 2 ? 0 : kz + 1;
    ky = kx == 2 ? 0 : kx + 1;
    sx = -d[kx] / d[kz];
    sy = -d[ky] / d[kz];
    sz = 1.0f / d[kz];
  }
};

struct TriangleHit {
  float t, u, v;
};

// True when the ray crosses triangle (p0, p1, p2) at tmin < t < tmax; fills t and the
// barycentrics u (weight of p1) and v (weight of p2).
inline bool intersectTriangle(const ShearedRay& r, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2,
                              float tmin, float tmax, TriangleHit& hit) {
  const float a[3] = {p0.x - r.origin[0], p0.y - r.origin[1], p0.z - r.origin[2]};
  const float b[3] = {p1.x - r.origin[0], p1.y - r.origin[1], p1.z - r.origin[2]};
  const float c[3] = {p2.x - r.origin[0], p2.y - r.origin[1], p2.z - r.origin[2]};
  const float ax = a[r.kx] + r.sx * a[r.kz], ay = a[r.ky] + r.sy * a[r.kz];
  const float bx = b[r.kx] + r.sx * b[r.kz], by = b[r.ky] + r.sy * b[r.kz];
  const float cx = c[r.kx] + r.sx * c[r.kz], cy = c[r.ky] + r.sy * c[r.kz];
  // Edge functions: e0 weighs p0 (edge p1p2), e1 weighs p1, e2 weighs p2.
  float e0 = cx * by - cy * bx;
  float e1 = ax * cy - ay * cx;
  float e2 = bx * ay - by * ax;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
    e0 = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
    e1 = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
    e2 = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
  }
  if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;
  const float tScaled = r.sz * (e0 * a[r.kz] + e1 * b[r.kz] + e2 * c[r.kz]);
  const float inverseDet = 1.0f / det;
  const float t = tScaled * inverseDet;
  if (!(t > tmin && t < tmax)) return false;
  hit = TriangleHit{t, e1 * inverseDet, e2 * inverseDet};
  return true;
}

}  // namespace bounce
