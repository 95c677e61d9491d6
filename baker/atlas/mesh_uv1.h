// Whether a mesh's own lightmap UVs (glTF TEXCOORD_1, Mesh::uv1) can serve an instance as they
// are: its [0,1]² square becomes a square region of `side` texels at the atlas's texel density.
#pragma once

#include <string>

#include "atlas/chart.h"
#include "scene/scene.h"

namespace bounce {

struct Uv1Check {
  bool usable = false;
  int side = 0;        // texels: edge of the instance's square region when usable
  std::string reason;  // why not, one clause (empty when usable or when the mesh has no uv1)
};

// Usable when every uv1 lies in [0,1]², no other surface crosses the mesh (Mesh::cutEdges
// empty of chart edges: its islands would run across a wall), no two triangles overlap in it, the
// region fits in the atlas, its islands keep `padding` texels apart (as generated charts do), and
// at most 10 % of the surface gets fewer than a quarter of the texels per m² the texel size asks
// for (the region is sized so that the mesh's uv1 area holds its world area).
Uv1Check checkMeshUv1(const Mesh& mesh, const WorldMesh& world, float texelSize, int padding,
                      int maxSize);

}  // namespace bounce
