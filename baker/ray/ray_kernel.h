// The ray kernel: closest-hit and occlusion queries against a static world-space triangle
// scene. Two backends behave identically up to floating-point ties: Embree 3 (the default)
// and our own binned-SAH BVH (portable fallback and cross-check).
// Distances are in metres along unit-length or non-unit directions alike (t is the ray
// parameter: hit point = origin + t·direction).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>

#include <glm/glm.hpp>

#include "scene/world_geometry.h"

namespace bounce {

struct Ray {
  glm::vec3 origin{0.0f};
  float tmin = 0.0f;
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  float tmax = std::numeric_limits<float>::infinity();
};

inline constexpr uint32_t kNoHit = 0xffffffffu;

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  uint32_t triangle = kNoHit;       // index into WorldGeometry::triangles
  float u = 0.0f, v = 0.0f;         // barycentrics: p = (1−u−v)·p0 + u·p1 + v·p2
  glm::vec3 geometricNormal{0.0f};  // unit, (p1−p0)×(p2−p0) direction (front side)

  bool valid() const { return triangle != kNoHit; }
};

enum class RayBackend : uint8_t { Embree, Bvh };

class RayKernel {
 public:
  virtual ~RayKernel() = default;
  virtual Hit intersect(const Ray& ray) const = 0;
  // True when any triangle lies strictly between tmin and tmax.
  virtual bool occluded(const Ray& ray) const = 0;
  // Batched forms (hits.size() == rays.size()); backends may use packets or streams.
  virtual void intersect(std::span<const Ray> rays, std::span<Hit> hits) const;
  virtual void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const;
  virtual const char* name() const = 0;
};

// Builds a kernel over `geometry`, which must outlive it. Degenerate (zero-area) triangles
// never produce hits.
std::unique_ptr<RayKernel> makeRayKernel(const WorldGeometry& geometry, RayBackend backend);
RayBackend parseRayBackend(const std::string& name);  // "embree" | "bvh"; throws otherwise

// A ray origin moved off a surface to avoid self-intersection: offset along the geometric
// normal n (towards the side `towards` points to) by a bound on the float rounding error of a
// hit point p computed from barycentrics: 16·2⁻²⁴·max|p| + 7.6 µm per axis, projected on n
// (1 to √3 times that: ≈ 1–1.7 mm at 1 km, 8–13 µm at the origin), so it clears the surface's
// own triangle anywhere in the scene without jumping past thin gaps (2 mm at 1 km).
glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 n, glm::vec3 towards);

}  // namespace bounce
