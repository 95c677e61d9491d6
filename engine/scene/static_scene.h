// What is static, decided once for the baker, the bake folder's rules and the renderer: an
// instance is static unless it is Mobility::Dynamic. A static instance at lightmapScale 0 has no
// lightmap region (its baked light comes from probes) but is static all the same: the bake
// traces it, VPL paths land on it, it shadows and reflects.
//   staticScene            the scene the bake traces (dynamic instances left out)
//   staticInstanceNumbers  the numbering staticScene gives the static instances
//   staticSurfaceArea      their surface A, m²: the VPL clamp's r = sqrt(A/(π·N))
//                          (bake_folder/vpl_clamp.h) and the atlas's staticArea (bake.json
//                          "atlas"."staticArea") are this one number
// GL-free.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "scene/scene.h"

namespace bounce {

struct WorldGeometry;

// `scene` without its dynamic instances (Mobility::Dynamic): the bake's VPL paths, lightmap
// texels and probes run in it, so that a dynamic object neither holds baked light (it would stay
// behind when the object moves) nor shadows it. The static instances keep their order
// (staticInstanceNumbers). Meshes and materials are kept as they are; lights keep their places
// (the bake names lights by index), but a light that moves (Light::mobility) is given zero
// power: nothing baked holds its light.
Scene staticScene(const Scene& scene);

// A file instance's number in staticScene(scene): the count of static instances before it.
inline constexpr uint32_t kNotStatic = std::numeric_limits<uint32_t>::max();
// Per instance of `scene`, its index in staticScene(scene); kNotStatic for a dynamic one.
std::vector<uint32_t> staticInstanceNumbers(const Scene& scene);

// Σ triangle areas of the static instances, m², non-finite areas skipped, in triangle order.
// `geometry` is flatten(scene); the baker passes its static scene (every instance static), the
// renderer and the bake folder's rules the whole one: both sum the same triangles in the same
// order, so they agree to the bit.
double staticSurfaceArea(const Scene& scene, const WorldGeometry& geometry);
// The same, flattening `scene` itself.
double staticSurfaceArea(const Scene& scene);
// Σ triangle areas of every triangle of `geometry`, m² (non-finite areas skipped).
double surfaceArea(const WorldGeometry& geometry);

}  // namespace bounce
