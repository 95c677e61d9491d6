#include "vpl/vpl_gather.h"

#include <optional>

namespace bounce {

namespace {

// A shadow ray is shortened by this fraction so that it stops short of the VPL's surface.
constexpr float kShadowShorten = 1e-4f;

bool visible(const RayKernel& kernel, glm::vec3 from, glm::vec3 fromNormal, const Vpl& vpl) {
  Ray ray;
  ray.origin = offsetRayOrigin(from, fromNormal, vpl.position - from);
  const glm::vec3 target = offsetRayOrigin(vpl.position, vpl.normal, from - vpl.position);
  ray.direction = target - ray.origin;
  ray.tmin = 0.0f;
  ray.tmax = 1.0f - kShadowShorten;
  if (!(glm::dot(ray.direction, ray.direction) > 0.0f)) return false;
  return !kernel.occluded(ray);
}

}  // namespace

VplIrradiance gatherVplIrradiance(std::span<const Vpl> vpls, glm::vec3 position, glm::vec3 normal,
                                  const RayKernel* kernel, float clampDistance) {
  VplIrradiance out;
  const double r2 = static_cast<double>(clampDistance) * clampDistance;
  const glm::dvec3 x(position), n(normal);
  for (const Vpl& vpl : vpls) {
    const std::optional<VplIrradiance> e = vplIrradiance(vpl, x, n, r2);
    if (!e) continue;
    if (kernel != nullptr && !visible(*kernel, position, normal, vpl)) continue;
    out += *e;
  }
  return out;
}

}  // namespace bounce
