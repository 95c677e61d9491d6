// Which rays the kernels trace at all. Debian's Embree is built with assertions: a NaN or
// infinite origin/direction aborts the process inside rtcIntersect, so both backends reject
// such rays up front and report "no hit" / "not occluded" for them.
#pragma once

#include <cmath>

#include "ray/ray_kernel.h"

namespace bounce {

// Embree's own limit for origin and direction components (FLT_LARGE in its ray.h).
inline constexpr float kLargestRayComponent = 1.844e18f;

inline bool isTraceable(const Ray& ray) {
  const auto finite = [](float x) { return std::abs(x) <= kLargestRayComponent; };  // false for NaN
  const glm::vec3 o = ray.origin, d = ray.direction;
  if (!(finite(o.x) && finite(o.y) && finite(o.z))) return false;
  if (!(finite(d.x) && finite(d.y) && finite(d.z))) return false;
  if (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f) return false;
  // tmin ≥ 0 and finite; tmax may be +∞ but not NaN; an empty interval hits nothing.
  if (!(ray.tmin >= 0.0f && ray.tmin <= kLargestRayComponent)) return false;
  return ray.tmax > ray.tmin;  // false for NaN tmax
}

}  // namespace bounce
