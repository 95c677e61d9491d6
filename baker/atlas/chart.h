// A chart: a connected set of one instance's triangles laid out flat in texel units, before
// packing. Internal to the atlas.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

enum class ChartSource : uint8_t {
  Planar,      // planar projection of a (near-)planar region
  Conformal,   // least-squares conformal map of a curved region
  MeshUv1,     // the instance's mesh's own uv1, the whole [0,1]² square, used as-is
  Degenerate,  // triangles without area (a point in the atlas)
  Bundle,      // sub-texel pieces side by side, each moved rigidly (chart_bundle.h)
};

struct Chart {
  uint32_t instance = 0;            // index into Scene::instances
  std::vector<uint32_t> triangles;  // triangle indices into the instance's mesh
  std::vector<glm::vec2> cornerUv;  // 3 per entry of `triangles`, texel units
  ChartSource source = ChartSource::Planar;
};

// The world-space triangles of one instance: its mesh's vertices under the instance transform.
struct WorldMesh {
  std::vector<glm::vec3> positions;  // metres, one per mesh vertex
  std::vector<uint32_t> indices;     // the mesh's, 3 per triangle (winding as in the mesh)
  std::vector<uint8_t> cutEdges;     // the mesh's (Mesh::cutEdges): charts never cross bits 0-2
  std::size_t triangleCount() const { return indices.size() / 3; }
  glm::vec3 corner(std::size_t triangle, int k) const {
    return positions[indices[3 * triangle + k]];
  }
  double area(std::size_t triangle) const;  // m²
};

}  // namespace bounce
