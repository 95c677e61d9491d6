#include "vpl/vpl_gather.h"

#include <cmath>
#include <numbers>

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
    const glm::dvec3 d = glm::dvec3(vpl.position) - x;
    const double d2 = glm::dot(d, d);
    if (!(d2 > 0.0)) continue;
    const double dist = std::sqrt(d2);
    const double cosX = glm::dot(n, d) / dist;
    const double cosV = -glm::dot(glm::dvec3(vpl.normal), d) / dist;
    if (cosX <= 0.0 || cosV <= 0.0) continue;
    if (kernel != nullptr && !visible(*kernel, position, normal, vpl)) continue;
    // I(ω) = Φ/π · cosθ_vpl (W/sr); E = I · cosθ_x / d².
    const glm::dvec3 intensity = glm::dvec3(vpl.flux) * (cosV / std::numbers::pi);
    const glm::dvec3 unclamped = intensity * (cosX / d2);
    const glm::dvec3 clamped = intensity * (cosX / std::max(d2, r2));
    out.irradiance += clamped;
    out.removed += unclamped - clamped;
  }
  return out;
}

}  // namespace bounce
