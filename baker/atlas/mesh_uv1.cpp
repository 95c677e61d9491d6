#include "atlas/mesh_uv1.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "atlas/uv_geometry.h"

namespace bounce {
namespace {

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Islands of the uv1 layout (triangles joined where they share a uv1 position, whatever the
// vertex indices) must keep `padding` texels between them at `side` texels per uv unit, as
// generated charts do: otherwise filtering mixes the light of unrelated surfaces.
std::string islandGapProblem(const Mesh& mesh, const std::vector<glm::vec2>& texelUv, int side,
                             int padding) {
  const auto triangles = static_cast<int>(mesh.triangleCount());
  std::vector<int> parent(static_cast<std::size_t>(triangles));
  for (int t = 0; t < triangles; ++t) parent[t] = t;
  std::map<std::pair<float, float>, int> firstAt;  // uv1 position → a triangle with it
  for (int t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::vec2 uv = mesh.uv1[mesh.indices[3 * t + k]];
      const auto [it, added] = firstAt.try_emplace({uv.x, uv.y}, t);
      if (!added) parent[findRoot(parent, t)] = findRoot(parent, it->second);
    }
  std::vector<int> owner(static_cast<std::size_t>(side) * side, -1);
  for (int t = 0; t < triangles; ++t) {
    const int island = findRoot(parent, t);
    bool close = false;
    forEachTouchedTexel(
        texelUv[3 * t], texelUv[3 * t + 1], texelUv[3 * t + 2], side, side, [&](int x, int y) {
          for (int yy = std::max(0, y - padding); yy <= std::min(side - 1, y + padding); ++yy)
            for (int xx = std::max(0, x - padding); xx <= std::min(side - 1, x + padding); ++xx) {
              const int o = owner[static_cast<std::size_t>(yy) * side + xx];
              close = close || (o >= 0 && o != island);
            }
          owner[static_cast<std::size_t>(y) * side + x] = island;
        });
    if (close) {
      std::ostringstream reason;
      reason << "its TEXCOORD_1 islands come closer than " << padding << " texels at " << side
             << " texels across";
      return reason.str();
    }
  }
  return "";
}

}  // namespace

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
  // A wall standing on the surface or passing through it cut it (scene/crossing_cuts.h): the cut
  // vertices are shared by both sides, so its uv1 islands run across the crossing and a texel (or
  // a bilinear lookup) would join two sides that see different light. Generated charts never
  // cross a cut edge.
  for (const uint8_t edges : mesh.cutEdges)
    if (edges & 0x7u) {
      check.reason =
          "another surface crosses it (a wall on it or through it), and its TEXCOORD_1 would "
          "carry light across";
      return check;
    }
  double uvArea = 0.0, worldArea = 0.0;
  for (std::size_t t = 0; t < world.triangleCount(); ++t) {
    const uint32_t* i = &mesh.indices[3 * t];
    uvArea +=
        std::abs(static_cast<double>(signedArea(mesh.uv1[i[0]], mesh.uv1[i[1]], mesh.uv1[i[2]])));
    worldArea += world.area(t);
  }
  if (!std::isfinite(worldArea)) {
    check.reason = "its positions are not finite";
    return check;
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
  if (const std::string gap = islandGapProblem(mesh, texelUv, check.side, padding); !gap.empty()) {
    check.reason = gap;
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
