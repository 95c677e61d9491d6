#include "trace/surface_point.h"

#include <algorithm>
#include <cmath>

#include "scene/surface_rules.h"
#include "trace/sampling.h"

namespace bounce {

namespace {

int wrap(int i, int n) {
  const int m = i % n;
  return m < 0 ? m + n : m;
}

}  // namespace

glm::vec3 sampleTexture(const Texture& texture, glm::vec2 uv) {
  if (texture.width <= 0 || texture.height <= 0 ||
      texture.texels.size() <
          static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height)) {
    return glm::vec3(1.0f);
  }
  // Texel (i, j) has its centre at ((i + ½)/w, (j + ½)/h).
  const float x = uv.x * static_cast<float>(texture.width) - 0.5f;
  const float y = uv.y * static_cast<float>(texture.height) - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return glm::vec3(1.0f);
  const float fx = std::floor(x);
  const float fy = std::floor(y);
  const float ax = x - fx;
  const float ay = y - fy;
  // Reduce before converting so that huge uvs do not overflow int.
  const int x0 =
      wrap(static_cast<int>(std::fmod(fx, static_cast<float>(texture.width))), texture.width);
  const int y0 =
      wrap(static_cast<int>(std::fmod(fy, static_cast<float>(texture.height))), texture.height);
  const int x1 = wrap(x0 + 1, texture.width);
  const int y1 = wrap(y0 + 1, texture.height);
  auto texel = [&](int i, int j) {
    return texture.texels[static_cast<std::size_t>(j) * static_cast<std::size_t>(texture.width) +
                          static_cast<std::size_t>(i)];
  };
  return (1.0f - ay) * ((1.0f - ax) * texel(x0, y0) + ax * texel(x1, y0)) +
         ay * ((1.0f - ax) * texel(x0, y1) + ax * texel(x1, y1));
}

bool makeSurfacePoint(const Scene& scene, const WorldGeometry& geometry, const Ray& ray,
                      const Hit& hit, SurfacePoint& point) {
  const glm::uvec3 tri = geometry.triangles[hit.triangle];
  const float b0 = 1.0f - hit.u - hit.v;
  const glm::vec3 p = b0 * geometry.positions[tri.x] + hit.u * geometry.positions[tri.y] +
                      hit.v * geometry.positions[tri.z];
  const glm::vec3 cross = geometry.triangleCross(hit.triangle);
  const float crossLength = glm::length(cross);
  if (!isFinite(p) || !(crossLength > 0.0f) || !std::isfinite(crossLength)) return false;
  const glm::vec3 front = cross / crossLength;
  const bool frontFace = glm::dot(front, ray.direction) < 0.0f;
  point.position = p;
  point.triangle = hit.triangle;
  point.barycentric = glm::vec2(hit.u, hit.v);
  point.geometricNormal = frontFace ? front : -front;

  // Interpolated shading normal: each corner's normal, or the geometric normal where the
  // corner's is unusable (the rule the renderer's corners follow), turned to the geometric
  // normal's side; a degenerate result falls back to the geometric normal.
  glm::vec3 ns = b0 * shadingNormalOr(geometry.normals[tri.x], front) +
                 hit.u * shadingNormalOr(geometry.normals[tri.y], front) +
                 hit.v * shadingNormalOr(geometry.normals[tri.z], front);
  ns = shadingNormalOr(ns, point.geometricNormal);
  if (glm::dot(ns, point.geometricNormal) < 0.0f) ns = -ns;
  if (glm::dot(ns, point.geometricNormal) < 1e-3f) ns = point.geometricNormal;
  point.shadingNormal = ns;

  const Material& material = materialOf(scene, geometry.triangleMaterial[hit.triangle]);
  glm::vec3 albedo = reflectance(material);
  if (material.albedoTexture && *material.albedoTexture < scene.textures.size()) {
    const glm::vec2 uv =
        b0 * geometry.uv0[tri.x] + hit.u * geometry.uv0[tri.y] + hit.v * geometry.uv0[tri.z];
    albedo *= sampleTexture(scene.textures[*material.albedoTexture], uv);
  }
  // ρ ≤ 1 keeps every path weight bounded; non-finite texels absorb (the renderer clamps the
  // same product).
  point.albedo = isFinite(albedo) ? glm::clamp(albedo, 0.0f, 1.0f) : glm::vec3(0.0f);
  const bool emits = frontFace || material.doubleSided;
  point.emitted = emits ? emittedRadiance(material) : glm::vec3(0.0f);
  return true;
}

}  // namespace bounce
