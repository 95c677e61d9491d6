#include "scene/emitter_irradiance.h"

#include <cmath>

#include "scene/light_falloff.h"

namespace bounce {
namespace {

// γ · (a×b)/|a×b| for one edge of the contour (0 for a degenerate edge).
glm::dvec3 edgeVector(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 c = glm::cross(a, b);
  const double s = glm::length(c);
  return s > 0.0 ? std::atan2(s, glm::dot(a, b)) * c / s : glm::dvec3(0.0);
}

}  // namespace

glm::vec3 emitterTriangleVector(const EmitterTriangle& triangle, glm::vec3 p, glm::vec3 n) {
  const glm::dvec3 v0(triangle.v0), v1(triangle.v1), v2(triangle.v2), x(p), normal(n);
  const glm::dvec3 front = glm::cross(v1 - v0, v2 - v0);
  const double frontLength = glm::length(front);
  if (!(frontLength > 0.0)) return glm::vec3(0.0f);
  const double height = glm::dot(front / frontLength, x - v0);
  if (std::abs(height) < 1e-5 || (height < 0.0 && !triangle.doubleSided)) return glm::vec3(0.0f);
  // Sutherland–Hodgman against the receiver's horizon plane: a triangle stays one polygon of at
  // most 4 corners, in the same winding.
  const glm::dvec3 corner[3] = {v0 - x, v1 - x, v2 - x};
  glm::dvec3 clipped[4];
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& a = corner[i];
    const glm::dvec3& b = corner[(i + 1) % 3];
    const double da = glm::dot(normal, a), db = glm::dot(normal, b);
    if (da >= 0.0) clipped[count++] = a;
    if ((da >= 0.0) != (db >= 0.0)) clipped[count++] = a + (b - a) * (da / (da - db));
  }
  if (count < 3) return glm::vec3(0.0f);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < count; ++i) sum += edgeVector(clipped[i], clipped[(i + 1) % count]);
  const glm::dvec3 phi = 0.5 * sum;
  return glm::vec3(glm::dot(normal, phi) < 0.0 ? -phi : phi);
}

glm::vec3 emitterTriangleIrradiance(const EmitterTriangle& triangle, glm::vec3 p, glm::vec3 n) {
  return triangle.radiance * glm::dot(n, emitterTriangleVector(triangle, p, n));
}

glm::vec3 areaLightIrradiance(const AreaLightSet& set, std::size_t light, glm::vec3 p,
                              glm::vec3 n) {
  const AreaLight& l = set.lights[light];
  glm::vec3 e(0.0f);
  for (uint32_t t = l.first; t < l.first + l.count; ++t)
    e += emitterTriangleIrradiance(set.triangles[t], p, n);
  return e;
}

std::array<glm::vec3, 3> areaLightIrradianceVectors(const AreaLightSet& set, std::size_t light,
                                                    glm::vec3 p, glm::vec3 n) {
  const AreaLight& l = set.lights[light];
  std::array<glm::vec3, 3> f{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  for (uint32_t t = l.first; t < l.first + l.count; ++t) {
    const glm::vec3 phi = emitterTriangleVector(set.triangles[t], p, n);
    for (int c = 0; c < 3; ++c)
      f[static_cast<std::size_t>(c)] += set.triangles[t].radiance[c] * phi;
  }
  return f;
}

std::array<glm::vec3, 3> punctualIrradianceVectors(const Light& light, glm::vec3 p, glm::vec3 n) {
  std::array<glm::vec3, 3> f{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  glm::vec3 l;
  float w = 1.0f;
  glm::vec3 power = light.intensity;
  if (light.type == LightType::Directional) {
    l = -glm::normalize(light.direction);
    power = light.irradiance;
  } else {
    const glm::vec3 toLight = light.position - p;
    const float r2 = glm::dot(toLight, toLight);
    if (!(r2 > 0.0f)) return f;
    l = toLight / std::sqrt(r2);
    w = 1.0f / r2;
    if (light.type == LightType::Spot)
      w *= spotFalloff(light, glm::dot(-l, glm::normalize(light.direction)));
  }
  if (!(glm::dot(n, l) > 0.0f) || !(w > 0.0f)) return f;
  for (int c = 0; c < 3; ++c) f[static_cast<std::size_t>(c)] = power[c] * w * l;
  return f;
}

}  // namespace bounce
