#include "ray/ray_kernel.h"

#include <algorithm>
#include <cmath>
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

// The offset is relative to the largest coordinate magnitude of p: a hit point computed in
// float (from barycentrics or o + t·d) carries an absolute error of a few tens of ulps of
// max|p| (ulp = 2^-23·max|p| ≈ 1.2e-7·max|p|). kRelativeOffset = 1e-4 is ~800 ulps: far above
// that error, yet only 0.1 mm for a point 1 m from the origin, so contact shadows in corners
// survive. kAbsoluteOffset covers points at (or very near) the world origin, where a relative
// offset would vanish; 1e-6 m is far below any feature size we model.
glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 n, glm::vec3 towards) {
  constexpr float kRelativeOffset = 1e-4f;
  constexpr float kAbsoluteOffset = 1e-6f;  // metres
  const float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float offset = kRelativeOffset * magnitude + kAbsoluteOffset;
  const float length = glm::length(n);  // n need not be unit; a zero n leaves p unchanged
  if (!(length > 0.0f)) return p;
  const glm::vec3 step = n * (offset / length);
  return glm::dot(n, towards) >= 0.0f ? p + step : p - step;
}

}  // namespace bounce
