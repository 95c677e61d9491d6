// Shading normals for meshes whose source has none.
#pragma once

#include "scene/scene.h"

namespace bounce {

// Gives every triangle its own three vertices carrying the triangle's geometric (flat) normal,
// (p1−p0)×(p2−p0) normalized, so counter-clockwise triangles keep facing their normal's side.
// glTF 2.0 requires flat normals when NORMAL is absent; bounce does the same for OBJ.
// Degenerate (zero-area) triangles get the normal (0,1,0): they receive no light anyway.
// Per-vertex attributes (uv0, uv1) are duplicated along with the positions.
void makeFlatNormals(Mesh& mesh);

}  // namespace bounce
