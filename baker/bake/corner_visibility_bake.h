// Bakes the static lights' visibility per triangle corner of the static instances the atlas
// leaves without a lightmap region (bake_folder/irradiance_probes.h, ProbeVisibility): their
// direct light is drawn live, and a lightmapped surface's baked V (light_visibility_bake.h) does
// not reach them. Corner k of a triangle takes the texels' estimator
// (estimatePointSetVisibility, the same pairs, weights and slots) over M points of the triangle
// drawn with density ∝ b_k, the corner's barycentric weight: b_k ~ Beta(2, 2), by inverting its
// CDF 3b² − 2b³, and the rest 1 − b_k split between the other two corners uniformly. Then
//   V_k = ∫ b_k E_l vis / ∫ b_k E_l   over the triangle,
// the V the renderer interpolates with the fragment's barycentric weights. The points' two
// coordinates are an R2 (Kronecker) sequence with a Cranley–Patterson rotation per corner,
// independent of the light samples' rotation, so every pair (x_k, y_k) is uniform over
// triangle × light.
//
// The corners that meet at one world vertex (flatten shares vertices within an instance, where
// the mesh does) are estimated once, over the vertex's ring: its triangles, each picked with
// probability ∝ its area, and a point in it with density ∝ the vertex's barycentric weight, so
// over the ring the density is ∝ the vertex's hat function φ and
//   V_v = ∫ φ E_l vis / ∫ φ E_l   over the ring,
// the value per-vertex interpolation wants (for a lone triangle, V_k above). Every corner at the
// vertex gets it: one estimate where there were as many as its triangles (about six on a smooth
// mesh), and no step between the triangles that share the vertex.
//
// Each vertex is computed from its own keys (seed, its first corner's number, light): the result
// does not depend on the thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bake_folder/irradiance_probes.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace bounce {

class RayKernel;
struct WorldGeometry;
struct TexelPoint;

// Samples a light per corner: half the texels' 64. A corner's V reaches the pixels through
// Gouraud interpolation over triangles much smaller than a texel, and the Conference Room's
// default bake drew the same frame with 32 (its 472 probe-lit pixels 5.58 → 5.49 % off the path
// tracer, the noise of the reference) while the stage took 10.6 → 5.4 s (docs/probes.md).
inline constexpr int kCornerSamplesPerLight = 32;

struct CornerVisibilitySettings {
  int samplesPerLight = kCornerSamplesPerLight;  // M: σ(V) ≤ 1/(2√M) per corner
  uint32_t seed = 0;
  int threads = 0;  // 0: all cores
};

// M points of world triangle `t` of `geometry` for its corner `corner` (0, 1, 2 in the world
// triangle's order), density ∝ the corner's barycentric weight, from `key`'s rotation.
std::vector<TexelPoint> cornerPoints(const WorldGeometry& geometry, uint32_t t, int corner,
                                     int count, uint32_t key);

// A triangle at a vertex: world triangle and which of its corners (0, 1, 2) is the vertex.
struct RingCorner {
  uint32_t triangle = 0;
  int corner = 0;
};

// M points over the triangles of a vertex's ring with density ∝ the vertex's hat function: each
// triangle takes its area's share (a Kronecker pick over the areas, from `key`), then
// its points as cornerPoints'. A ring of one triangle gives cornerPoints' points.
std::vector<TexelPoint> vertexRingPoints(const WorldGeometry& geometry,
                                         std::span<const RingCorner> ring, int count, uint32_t key);

struct CornerVisibilityBake {
  ProbeVisibility visibility;
  // Per instance of `tracedInstances` (in order): its first corner and its corner count
  // (3 per triangle, in its mesh's `indices` order).
  std::vector<uint32_t> firstCorner, cornerCount;
  uint64_t vertices = 0;  // world vertices estimated (each once, for all its corners)
  uint64_t rays = 0;
  double seconds = 0.0;
};

// `tracedInstances`: the instances to bake, as indices of `geometry`'s triangleInstance (the
// static scene's numbering), ascending; `mirrored[i]` whether instance i's transform mirrors
// (flatten swapped corners 1 and 2 of its triangles: the result is put back in the mesh's
// order). `lights` must hold the static lights first; `punctual` is Scene::lights.
CornerVisibilityBake bakeCornerVisibility(const AreaLightSet& lights,
                                          std::span<const Light> punctual,
                                          const WorldGeometry& geometry, const RayKernel& kernel,
                                          std::span<const uint32_t> tracedInstances,
                                          std::span<const uint8_t> mirrored,
                                          const CornerVisibilitySettings& settings);

}  // namespace bounce
