#include "bake/irradiance_cache.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bake/texel_coverage.h"
#include "bake_folder/lightmap_layout.h"
#include "scene/scene.h"
#include "scene/world_geometry.h"

namespace bounce {

IrradianceCache::IrradianceCache(const Scene& scene, const WorldGeometry& geometry,
                                 const LightmapLayout& layout, std::array<Image, 2> halves,
                                 std::vector<uint8_t> readable, bool holdsDirect)
    : geometry_(geometry),
      irradiance_(std::move(halves)),
      readable_(std::move(readable)),
      holdsDirect_(holdsDirect) {
  const std::size_t texels =
      static_cast<std::size_t>(layout.width) * static_cast<std::size_t>(layout.height);
  for (const Image& map : irradiance_)
    if (map.width != layout.width || map.height != layout.height || readable_.size() != texels)
      throw std::invalid_argument("irradiance cache: a half map is not the layout's size");
  if (scene.triangleCount() != geometry.triangleCount())
    throw std::invalid_argument("irradiance cache: world geometry does not match the scene");
  triangles_.assign(geometry.triangleCount(), TriangleUv{});
  const std::vector<InstanceBase> bases = instanceBases(scene);
  const glm::vec2 size(static_cast<float>(layout.width), static_cast<float>(layout.height));
  for (const InstanceLightmapUv& region : layout.instances) {
    if (region.instance >= scene.instances.size())
      throw std::invalid_argument("irradiance cache: the layout names instance " +
                                  std::to_string(region.instance) + ", not in the scene");
    const Mesh& mesh = scene.meshes[scene.instances[region.instance].mesh];
    if (region.cornerUv.size() != mesh.indices.size())
      throw std::invalid_argument("irradiance cache: the layout of instance " +
                                  std::to_string(region.instance) + " has " +
                                  std::to_string(region.cornerUv.size()) + " corners, its mesh " +
                                  std::to_string(mesh.indices.size()));
    const InstanceBase base = bases[region.instance];
    for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t) {
      const uint32_t world = base.triangle + static_cast<uint32_t>(t);
      TriangleUv& out = triangles_[world];
      // flatten() swaps corners 1 and 2 of a mirroring instance's triangles.
      const bool swapped = geometry.triangles[world].y != base.vertex + mesh.indices[3 * t + 1];
      out.corner[0] = region.cornerUv[3 * t] * size;
      out.corner[1] = region.cornerUv[3 * t + (swapped ? 2 : 1)] * size;
      out.corner[2] = region.cornerUv[3 * t + (swapped ? 1 : 2)] * size;
      // Texel edge on the surface: sqrt(world area / atlas area in texels²).
      const glm::vec2 a = out.corner[1] - out.corner[0], b = out.corner[2] - out.corner[0];
      const float atlasArea = 0.5f * std::abs(a.x * b.y - a.y * b.x);
      const float worldArea = 0.5f * glm::length(geometry.triangleCross(world));
      out.texelEdge = atlasArea > 0.0f && std::isfinite(worldArea / atlasArea)
                          ? std::sqrt(worldArea / atlasArea)
                          : layout.texelSize;
      if (!(out.texelEdge > 0.0f)) out.texelEdge = layout.texelSize;
    }
  }
}

std::optional<std::size_t> IrradianceCache::texelAt(uint32_t triangle, glm::vec2 uv) const {
  if (triangle >= triangles_.size() || !(triangles_[triangle].texelEdge > 0.0f))
    return std::nullopt;
  const TriangleUv& t = triangles_[triangle];
  const glm::vec2 p = (1.0f - uv.x - uv.y) * t.corner[0] + uv.x * t.corner[1] + uv.y * t.corner[2];
  const Image& map = irradiance_[0];
  const int x = std::clamp(static_cast<int>(std::floor(p.x)), 0, map.width - 1);
  const int y = std::clamp(static_cast<int>(std::floor(p.y)), 0, map.height - 1);
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(map.width) +
         static_cast<std::size_t>(x);
}

std::optional<glm::vec3> IrradianceCache::irradianceAt(const SurfacePoint& at, glm::vec3 from,
                                                       int h) const {
  const std::optional<std::size_t> texel = texelAt(at.triangle, at.barycentric);
  if (!texel || !readable_[*texel]) return std::nullopt;  // no region, or not a valid texel
  const glm::vec3 travelled = at.position - from;
  // Back face: the ray runs along the front (counter-clockwise) normal.
  if (glm::dot(travelled, geometry_.triangleCross(at.triangle)) >= 0.0f) return std::nullopt;
  const float close = kCloseTexels * triangles_[at.triangle].texelEdge;
  if (glm::dot(travelled, travelled) < close * close) return std::nullopt;
  return irradiance_[h & 1].pixels[*texel];
}

}  // namespace bounce
