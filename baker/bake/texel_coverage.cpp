#include "bake/texel_coverage.h"

#include "atlas/uv_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "trace/sampling.h"
#include "trace/sobol_sampler.h"

namespace bounce {

namespace {

float cross2(glm::vec2 a, glm::vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// One triangle's atlas image (texel space, counter-clockwise) and its world vertices.
struct TriangleImage {
  std::array<glm::vec2, 3> uv;
  std::array<uint32_t, 3> vertex;  // WorldGeometry vertex of each corner, same order as uv
  uint32_t triangle = 0;
};

// A triangle's part of one texel: a convex polygon in texel space.
struct Fragment {
  uint32_t texel = 0;
  uint32_t image = 0;  // index into the TriangleImage list
  uint8_t count = 0;
  std::array<glm::vec2, 8> polygon;
};

}  // namespace

std::vector<InstanceBase> instanceBases(const Scene& scene) {
  std::vector<InstanceBase> bases(scene.instances.size());
  InstanceBase next;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Mesh& mesh = scene.meshes.at(scene.instances[i].mesh);
    bases[i] = next;
    next.triangle += static_cast<uint32_t>(mesh.indices.size() / 3);
    next.vertex += static_cast<uint32_t>(mesh.positions.size());
  }
  return bases;
}

TexelCoverage buildTexelCoverage(const Scene& scene, const WorldGeometry& geometry,
                                 const LightmapLayout& layout, int pointsPerTexel, uint32_t seed) {
  if (layout.width < 1 || layout.height < 1)
    throw std::invalid_argument("lightmap layout has no texels");
  if (pointsPerTexel < 1) throw std::invalid_argument("pointsPerTexel must be at least 1");
  const glm::vec2 size(static_cast<float>(layout.width), static_cast<float>(layout.height));

  const std::vector<InstanceBase> bases = instanceBases(scene);
  if (scene.triangleCount() != geometry.triangleCount())
    throw std::invalid_argument("world geometry does not match the scene");

  std::vector<TriangleImage> images;
  std::vector<Fragment> fragments;
  for (const InstanceLightmapUv& region : layout.instances) {
    if (region.instance >= scene.instances.size())
      throw std::invalid_argument("lightmap layout names an instance the scene does not have");
    const Mesh& mesh = scene.meshes[scene.instances[region.instance].mesh];
    if (region.cornerUv.size() != mesh.indices.size())
      throw std::invalid_argument("lightmap layout of instance " + std::to_string(region.instance) +
                                  " does not have 3 UVs per triangle");
    for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
      TriangleImage image;
      image.triangle = bases[region.instance].triangle + static_cast<uint32_t>(t);
      for (int k = 0; k < 3; ++k) {
        image.uv[k] = region.cornerUv[3 * t + k] * size;
        image.vertex[k] = bases[region.instance].vertex + mesh.indices[3 * t + k];
      }
      if (!(std::abs(cross2(image.uv[1] - image.uv[0], image.uv[2] - image.uv[0])) > 0.0f))
        continue;  // no area in the atlas: nothing to bake
      const auto imageIndex = static_cast<uint32_t>(images.size());
      images.push_back(image);
      const glm::vec2 lo = glm::min(image.uv[0], glm::min(image.uv[1], image.uv[2]));
      const glm::vec2 hi = glm::max(image.uv[0], glm::max(image.uv[1], image.uv[2]));
      const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
      const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
      const int x1 = std::min(layout.width - 1, static_cast<int>(std::floor(hi.x)));
      const int y1 = std::min(layout.height - 1, static_cast<int>(std::floor(hi.y)));
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const glm::vec2 texelMin(static_cast<float>(x), static_cast<float>(y));
          const std::vector<glm::vec2> poly =
              clipTriangleToBox(image.uv[0], image.uv[1], image.uv[2], texelMin, texelMin + 1.0f);
          if (poly.size() < 3 || !(polygonArea(poly) > 0.0f)) continue;
          Fragment f;
          f.texel = static_cast<uint32_t>(y * layout.width + x);
          f.image = imageIndex;
          f.count = static_cast<uint8_t>(std::min<std::size_t>(poly.size(), f.polygon.size()));
          std::copy_n(poly.begin(), f.count, f.polygon.begin());
          fragments.push_back(f);
        }
      }
    }
  }
  std::stable_sort(fragments.begin(), fragments.end(),
                   [](const Fragment& a, const Fragment& b) { return a.texel < b.texel; });

  TexelCoverage coverage;
  coverage.width = layout.width;
  coverage.height = layout.height;
  coverage.first.assign(coverage.texelCount() + 1, 0);
  coverage.coveredArea.assign(coverage.texelCount(), 0.0f);

  // Fan triangles of one texel's polygons, with their cumulative areas.
  struct FanTriangle {
    glm::vec2 a, b, c;
    uint32_t image;
  };
  std::vector<FanTriangle> fan;
  std::vector<float> cumulative;
  // Fragments come sorted by texel: their distinct texels bound the points, so the list is
  // allocated once (growing it by doubling held up to twice the memory: bake_memory.h).
  std::size_t fragmentTexels = 0;
  for (std::size_t i = 0; i < fragments.size(); ++i)
    fragmentTexels += i == 0 || fragments[i].texel != fragments[i - 1].texel ? 1 : 0;
  coverage.points.reserve(fragmentTexels * static_cast<std::size_t>(std::max(pointsPerTexel, 0)));
  std::size_t f = 0;
  for (std::size_t texel = 0; texel < coverage.texelCount(); ++texel) {
    coverage.first[texel] = static_cast<uint32_t>(coverage.points.size());
    fan.clear();
    cumulative.clear();
    float total = 0.0f;
    for (; f < fragments.size() && fragments[f].texel == texel; ++f) {
      const Fragment& frag = fragments[f];
      for (int i = 1; i + 1 < frag.count; ++i) {
        const FanTriangle tri{frag.polygon[0], frag.polygon[i], frag.polygon[i + 1], frag.image};
        const float area = 0.5f * std::abs(cross2(tri.b - tri.a, tri.c - tri.a));
        if (!(area > 0.0f)) continue;
        total += area;
        fan.push_back(tri);
        cumulative.push_back(total);
      }
    }
    if (fan.empty()) continue;
    coverage.coveredArea[texel] = total;
    SobolSampler sampler(seed, static_cast<uint32_t>(texel));
    for (int s = 0; s < pointsPerTexel; ++s) {
      sampler.startSample(static_cast<uint32_t>(s));
      glm::vec2 u = sampler.get2D();
      // Pick a fan triangle by area with u.x, then reuse u.x's position inside its interval.
      const float target = u.x * total;
      const std::size_t k = std::min<std::size_t>(
          static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), target) -
                                   cumulative.begin()),
          fan.size() - 1);
      const float lo = k == 0 ? 0.0f : cumulative[k - 1];
      u.x = std::clamp((target - lo) / (cumulative[k] - lo), 0.0f, 0.99999994f);
      const FanTriangle& tri = fan[k];
      const glm::vec2 bary = sampleUniformTriangle(u);
      const glm::vec2 q = (1.0f - bary.x - bary.y) * tri.a + bary.x * tri.b + bary.y * tri.c;
      // Barycentrics of q in the mesh triangle's atlas image → world point and normal.
      const TriangleImage& image = images[tri.image];
      const glm::vec2 e1 = image.uv[1] - image.uv[0], e2 = image.uv[2] - image.uv[0];
      const float det = cross2(e1, e2);
      const float w1 = std::clamp(cross2(q - image.uv[0], e2) / det, 0.0f, 1.0f);
      const float w2 = std::clamp(cross2(e1, q - image.uv[0]) / det, 0.0f, 1.0f - w1);
      const float w0 = 1.0f - w1 - w2;
      TexelPoint point;
      point.position = w0 * geometry.positions[image.vertex[0]] +
                       w1 * geometry.positions[image.vertex[1]] +
                       w2 * geometry.positions[image.vertex[2]];
      const glm::vec3 cross = geometry.triangleCross(image.triangle);
      const float crossLength = glm::length(cross);
      if (!(crossLength > 0.0f) || !std::isfinite(crossLength)) continue;  // degenerate in 3D
      point.geometricNormal = cross / crossLength;
      glm::vec3 n = w0 * geometry.normals[image.vertex[0]] +
                    w1 * geometry.normals[image.vertex[1]] + w2 * geometry.normals[image.vertex[2]];
      const float nLength = glm::length(n);
      n = nLength > 0.0f ? n / nLength : point.geometricNormal;
      // The shading normal lies on the front face's side (as SurfacePoint's invariant).
      point.shadingNormal = glm::dot(n, point.geometricNormal) > 0.0f ? n : point.geometricNormal;
      point.texelPosition = q;
      point.triangle = image.triangle;
      coverage.points.push_back(point);
    }
  }
  coverage.first[coverage.texelCount()] = static_cast<uint32_t>(coverage.points.size());
  return coverage;
}

}  // namespace bounce
