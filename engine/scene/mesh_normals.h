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

// Makes every shading normal unit length. A zero or non-finite normal (a file's NORMAL data may
// hold them) becomes the area-weighted sum of the geometric normals (p1−p0)×(p2−p0) of the
// triangles using that vertex, normalized; where that sum is zero too (no triangle, or
// opposing faces cancel), each triangle using the vertex gets its own copy of it carrying the
// triangle's flat normal, as makeFlatNormals does. Valid normals are only normalized.
void repairNormals(Mesh& mesh);

}  // namespace bounce
