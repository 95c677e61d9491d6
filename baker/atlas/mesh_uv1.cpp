#include "atlas/mesh_uv1.h"

#include <cmath>
#include <sstream>

#include "atlas/uv_geometry.h"

namespace bounce {

Uv1Check checkMeshUv1(const Mesh& mesh, const WorldMesh& world, float texelSize, int padding,
                      int maxSize) {
  Uv1Check check;
  if (mesh.uv1.empty()) return check;
  for (const glm::vec2 uv : mesh.uv1)
    if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
      std::ostringstream reason;
      reason << "its TEXCOORD_1 leaves [0,1] (" << uv.x << ", " << uv.y << ")";
      check.reason = reason.str();
      return check;
    }
  double uvArea = 0.0, worldArea = 0.0;
  for (std::size_t t = 0; t < world.triangleCount(); ++t) {
    const uint32_t* i = &mesh.indices[3 * t];
    uvArea +=
        std::abs(static_cast<double>(signedArea(mesh.uv1[i[0]], mesh.uv1[i[1]], mesh.uv1[i[2]])));
    worldArea += world.area(t);
  }
  if (!(uvArea > 0.0)) {
    check.reason = "its TEXCOORD_1 has no area";
    return check;
  }
  // Texels per uv unit so that the uv1 area holds the world area at the texel density.
  const double side = std::ceil(std::sqrt(worldArea / uvArea) / static_cast<double>(texelSize));
  if (side + padding > maxSize) {
    check.reason = "its TEXCOORD_1 region would exceed the largest atlas";
    return check;
  }
  check.side = std::max(1, static_cast<int>(side));
  const float s = static_cast<float>(check.side);
  std::vector<glm::vec2> texelUv;
  texelUv.reserve(mesh.indices.size());
  for (const uint32_t i : mesh.indices) texelUv.push_back(mesh.uv1[i] * s);
  if (const auto pair = findOverlappingTriangles(texelUv, 1e-3f)) {
    std::ostringstream reason;
    reason << "triangles " << pair->first << " and " << pair->second
           << " overlap in its TEXCOORD_1";
    check.reason = reason.str();
    return check;
  }
  const double wanted = 1.0 / (static_cast<double>(texelSize) * texelSize);  // texels per m²
  double starved = 0.0;
  for (std::size_t t = 0; t < world.triangleCount(); ++t) {
    const double texels = std::abs(
        static_cast<double>(signedArea(texelUv[3 * t], texelUv[3 * t + 1], texelUv[3 * t + 2])));
    if (texels < 0.25 * wanted * world.area(t)) starved += world.area(t);
  }
  if (starved > 0.1 * worldArea) {
    std::ostringstream reason;
    reason << "its TEXCOORD_1 gives " << static_cast<int>(100.0 * starved / worldArea)
           << "% of the surface fewer than a quarter of the texels per m² asked for";
    check.reason = reason.str();
    return check;
  }
  check.usable = true;
  return check;
}

}  // namespace bounce
