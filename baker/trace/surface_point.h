// What the path tracer knows about a ray's hit: position, normals oriented towards the side
// the ray came from, the Lambertian albedo and the radiance the surface emits back along the
// ray.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "ray/ray_kernel.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"

namespace bounce {

struct SurfacePoint {
  glm::vec3 position{0.0f};  // world, metres (barycentric interpolation of the vertices)
  // Both unit normals lie on the incoming ray's side: dot(geometricNormal, −ray.direction) ≥ 0
  // and dot(shadingNormal, geometricNormal) > 0. The Lambertian surface reflects on that side
  // whichever face was hit (an opaque wall reflects on both faces).
  glm::vec3 geometricNormal{0.0f, 0.0f, 1.0f};
  glm::vec3 shadingNormal{0.0f, 0.0f, 1.0f};
  glm::vec3 albedo{0.0f};   // ρ in [0,1]: Material::albedo × base colour texture at uv0
  glm::vec3 emitted{0.0f};  // W/(sr·m²) towards the ray origin (front face unless doubleSided)
  uint32_t triangle = kNoHit;
  // The hit's barycentrics (Hit::u, Hit::v) on `triangle`'s corners 1 and 2 (WorldGeometry order).
  glm::vec2 barycentric{0.0f};
};

// Returns false (leaving `point` unspecified) when the hit's geometry is not finite: such a
// path ends there and contributes nothing more.
bool makeSurfacePoint(const Scene& scene, const WorldGeometry& geometry, const Ray& ray,
                      const Hit& hit, SurfacePoint& point);

// Bilinear lookup with repeat wrapping; uv (0,0) is the top-left corner of the texture.
glm::vec3 sampleTexture(const Texture& texture, glm::vec2 uv);

}  // namespace bounce
