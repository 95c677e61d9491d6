#include "render/static_direct_texels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "scene/emitter_irradiance.h"

namespace bounce {
namespace {

// The surface point a texel stands for: the nearest one found so far (distance in texels).
struct TexelSurface {
  float distance = std::numeric_limits<float>::infinity();
  glm::vec3 position{0.0f};  // world, metres
  glm::vec3 normal{0.0f};    // world, unit
};

// The point of triangle (a, b, c) nearest to p, as barycentric weights of a, b, c
// (forward.frag's closestPointInTriangle, which clamps the shader's lookups the same way).
glm::vec3 nearestBarycentric(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  const auto cross2 = [](glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; };
  const float area = cross2(b - a, c - a);
  const float wa = cross2(b - p, c - p) / area, wb = cross2(c - p, a - p) / area;
  const float wc = 1.0f - wa - wb;
  if (wa >= 0.0f && wb >= 0.0f && wc >= 0.0f) return {wa, wb, wc};
  // Outside: the nearest point of the three edges.
  glm::vec3 best(1.0f, 0.0f, 0.0f);
  float bestDistance = std::numeric_limits<float>::infinity();
  const glm::vec2 corner[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const glm::vec2 s = corner[k], e = corner[(k + 1) % 3], d = e - s;
    const float dd = glm::dot(d, d);
    const float t = dd > 0.0f ? std::clamp(glm::dot(p - s, d) / dd, 0.0f, 1.0f) : 0.0f;
    const glm::vec2 q = s + t * d;
    const float distance = glm::dot(p - q, p - q);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = glm::vec3(0.0f);
      best[k] = 1.0f - t;
      best[(k + 1) % 3] = t;
    }
  }
  return best;
}

// Each texel's nearest surface point over every lightmapped instance's triangles.
std::vector<TexelSurface> texelSurfaces(const Scene& scene, const LightmapLayout& layout) {
  const int width = layout.width, height = layout.height;
  std::vector<TexelSurface> texels(static_cast<std::size_t>(width) *
                                   static_cast<std::size_t>(height));
  const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
  for (const InstanceLightmapUv& region : layout.instances) {
    const Instance& instance = scene.instances.at(region.instance);
    const Mesh& mesh = scene.meshes.at(instance.mesh);
    if (region.cornerUv.size() != mesh.indices.size())
      throw std::invalid_argument("staticDirectTexels: instance " + instance.name +
                                  "'s lightmap corners do not match its mesh");
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.transform)));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec2 uv[3];
      glm::vec3 position[3], normal[3];
      for (std::size_t k = 0; k < 3; ++k) {
        uv[k] = region.cornerUv[t + k] * size;  // texel units: centres at i + ½
        const uint32_t v = mesh.indices[t + k];
        position[k] = glm::vec3(instance.transform * glm::vec4(mesh.positions[v], 1.0f));
        normal[k] = normalMatrix * mesh.normals[v];
      }
      const float area =
          (uv[1].x - uv[0].x) * (uv[2].y - uv[0].y) - (uv[1].y - uv[0].y) * (uv[2].x - uv[0].x);
      if (!(std::abs(area) > 0.0f)) continue;  // no texel reads a triangle without UV area
      const glm::vec2 lo = glm::min(uv[0], glm::min(uv[1], uv[2]));
      const glm::vec2 hi = glm::max(uv[0], glm::max(uv[1], uv[2]));
      // Centres within one texel of the triangle: i + ½ in (lo − 1, hi + 1).
      const int x0 = std::max(0, static_cast<int>(std::floor(lo.x - 1.5f)));
      const int x1 = std::min(width - 1, static_cast<int>(std::ceil(hi.x + 0.5f)));
      const int y0 = std::max(0, static_cast<int>(std::floor(lo.y - 1.5f)));
      const int y1 = std::min(height - 1, static_cast<int>(std::ceil(hi.y + 0.5f)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
          const glm::vec3 b = nearestBarycentric(centre, uv[0], uv[1], uv[2]);
          const glm::vec2 q = b.x * uv[0] + b.y * uv[1] + b.z * uv[2];
          const glm::vec2 d = glm::abs(q - centre);
          if (!(std::max(d.x, d.y) < 1.0f)) continue;  // no bilinear tap reaches it
          TexelSurface& texel =
              texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                     static_cast<std::size_t>(x)];
          const float distance = glm::length(q - centre);
          if (!(distance < texel.distance)) continue;  // ties: the first triangle keeps it
          const glm::vec3 n = b.x * normal[0] + b.y * normal[1] + b.z * normal[2];
          texel.distance = distance;
          texel.position = b.x * position[0] + b.y * position[1] + b.z * position[2];
          texel.normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f);
        }
    }
  }
  return texels;
}

}  // namespace

std::size_t PrecomputedLights::areaLights() const {
  return area ? std::min({areaCount, area->staticCount(), area->lights.size()}) : 0;
}

bool PrecomputedLights::areaComputed(std::size_t l) const {
  return l < areaLights() && !area->lights[l].bakeDirect;
}

void addStaticDirect(const PrecomputedLights& lights, const TexelVisibility& visible,
                     uint32_t areaLightCount, glm::vec3 x, glm::vec3 n, glm::vec3 f[3]) {
  const auto add = [&](const std::array<glm::vec3, 3>& light, float v) {
    for (std::size_t c = 0; c < 3; ++c) f[c] += v * light[c];
  };
  for (std::size_t l = 0; l < lights.areaLights(); ++l) {
    if (!lights.areaComputed(l)) continue;
    const float v = visibleFraction(visible, static_cast<uint16_t>(l));
    if (v > 0.0f) add(areaLightIrradianceVectors(*lights.area, l, x, n), v);
  }
  for (std::size_t i = 0; i < lights.punctual.size(); ++i) {
    if (!lights.punctualComputed(i)) continue;
    const float v = visibleFraction(visible, static_cast<uint16_t>(areaLightCount + i));
    if (v > 0.0f) add(punctualIrradianceVectors(lights.punctual[i], x, n), v);
  }
}

std::vector<glm::vec3> staticDirectTexels(const Scene& scene, const LightmapLayout& layout,
                                          const BakedVisibility& visibility,
                                          const PrecomputedLights& lights) {
  if (visibility.width != layout.width || visibility.height != layout.height)
    throw std::invalid_argument("staticDirectTexels: the visibility is not the layout's size");
  const std::vector<TexelSurface> surfaces = texelSurfaces(scene, layout);
  const std::size_t layer = surfaces.size();
  std::vector<glm::vec3> direct(3 * layer, glm::vec3(0.0f));
  tbb::parallel_for(std::size_t{0}, layer, [&](std::size_t t) {
    const TexelSurface& surface = surfaces[t];
    if (!std::isfinite(surface.distance) || surface.normal == glm::vec3(0.0f)) return;
    glm::vec3 f[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    addStaticDirect(lights, visibility.texels[t], visibility.lightCount, surface.position,
                    surface.normal, f);
    for (std::size_t c = 0; c < 3; ++c) direct[c * layer + t] = f[c];
  });
  return direct;
}

}  // namespace bounce
