#include "ray/ray_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "ray/ray_kernel_bvh.h"
#include "ray/ray_kernel_embree.h"

namespace bounce {

void RayKernel::intersect(std::span<const Ray> rays, std::span<Hit> hits) const {
  if (hits.size() != rays.size())
    throw std::invalid_argument("RayKernel::intersect: size mismatch");
  for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = intersect(rays[i]);
}

void RayKernel::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  if (occluded.size() != rays.size())
    throw std::invalid_argument("RayKernel::occluded: size mismatch");
  for (std::size_t i = 0; i < rays.size(); ++i) occluded[i] = this->occluded(rays[i]) ? 1 : 0;
}

std::unique_ptr<RayKernel> makeRayKernel(const WorldGeometry& geometry, RayBackend backend) {
  switch (backend) {
    case RayBackend::Embree:
      return std::make_unique<EmbreeKernel>(geometry);
    case RayBackend::Bvh:
      return std::make_unique<BvhKernel>(geometry);
  }
  throw std::invalid_argument("makeRayKernel: unknown backend");
}

RayBackend parseRayBackend(const std::string& name) {
  if (name == "embree") return RayBackend::Embree;
  if (name == "bvh") return RayBackend::Bvh;
  throw std::invalid_argument("unknown ray backend '" + name +
                              "': expected 'embree' (Embree 3) or 'bvh' (bounce's own BVH)");
}

// The offset is a bound on float rounding, not a fixed fraction of |p|. Let M be the largest
// coordinate magnitude (of p, standing in for the triangle's vertices) and u = 2^-24 the unit
// roundoff (1 ulp of M is between u·M and 2u·M).
// - A hit point from barycentrics, p = (1−b1−b2)·p0 + b1·p1 + b2·p2 in float, lies off the
//   triangle's plane by at most ≈ 5u·M per axis: 2u from b0 = 1−b1−b2 (any b1, b2 with
//   b0 = 1−b1−b2 exact give a point in the plane, so errors in the kernel's b1, b2 only slide
//   p within it), 3u from the three products and two sums (γ3·Σ|b_i·p_i| ≤ γ3·M).
// - The kernels test triangles in coordinates relative to the ray origin; the vertex − origin
//   differences of a nearby triangle are exact (Sterbenz), and the plane-distance and t
//   evaluations add a few more u·M for a triangle of size ≲ M.
// kRelativeError = 16u (8–16 ulps of M) per axis covers both with a factor ~2 to spare
// (measured: 1u plus the final one-float rounding already keeps every ray of
// tests/ray/offset_test.cpp off its own triangle, spheres of 1 cm … 1 km, both backends).
// Projected on the unit normal, a per-axis error box e reaches e·(|n.x|+|n.y|+|n.z|), between
// e and √3·e. At 1000 m that is 0.96–1.67 mm (vs 10 cm before): thin gaps of 2 mm still cast
// shadows. Near the world origin max|p| → 0 while the triangle's vertices need not be small (a
// hit near the origin on a large triangle carries the error of its vertices' magnitude), so
// kAbsoluteError is the relative bound of a point 8 m out: any triangle of a room-sized scene
// around the origin is covered wherever it is hit; 7.6 µm is far below any modelled feature.
// Hits near the origin on triangles with vertices beyond ~8 m are not covered (see
// docs/ray_kernel.md). Finally each coordinate is rounded away from p by one float, so that
// rounding p + offset·n to float never eats into the offset.
glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 n, glm::vec3 towards) {
  constexpr float kUnitRoundoff = 0x1p-24f;
  constexpr float kRelativeError = 16.0f * kUnitRoundoff;
  constexpr float kAbsoluteError = kRelativeError * 8.0f;  // metres
  const float length = glm::length(n);  // n need not be unit; a zero n leaves p unchanged
  if (!(length > 0.0f)) return p;
  glm::vec3 unit = n / length;
  if (glm::dot(n, towards) < 0.0f) unit = -unit;
  const float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float error = kRelativeError * magnitude + kAbsoluteError;  // per axis
  const float offset = error * (std::abs(unit.x) + std::abs(unit.y) + std::abs(unit.z));
  glm::vec3 origin = p + offset * unit;
  for (int axis = 0; axis < 3; ++axis) {
    if (unit[axis] > 0.0f)
      origin[axis] = std::nextafter(origin[axis], std::numeric_limits<float>::infinity());
    else if (unit[axis] < 0.0f)
      origin[axis] = std::nextafter(origin[axis], -std::numeric_limits<float>::infinity());
  }
  return origin;
}

}  // namespace bounce
