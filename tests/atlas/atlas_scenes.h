// Scenes built in code for the atlas tests: one mesh per shape, placed by instances.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce::test {

// Adds a mesh and returns its index. Quad: the unit square in z = 0, facing +z, as two triangles.
uint32_t addUnitQuadMesh(Scene& scene);
// An axis-aligned unit cube [0,1]³, 24 vertices (split per face, as glTF exporters do).
uint32_t addUnitCubeMesh(Scene& scene);
// A UV sphere of radius 1, `rings` × `segments`, vertices shared (poles single).
uint32_t addSphereMesh(Scene& scene, int rings, int segments);
// An open cylinder of radius 1 and height 2 around y, `segments` around, vertices shared.
uint32_t addCylinderMesh(Scene& scene, int segments);
// Places `mesh` with `transform`.
void addInstance(Scene& scene, uint32_t mesh, const glm::mat4& transform,
                 Mobility mobility = Mobility::Static);

}  // namespace bounce::test
