// Area lights: the scene's emissive triangles cut into lights by their shape, not by how the file
// groups them. GL-free: the renderer draws and shadows these lights, the baker bakes each one's
// visibility per lightmap texel, and both get the same list from the same scene.
// Lengths in metres, radiance W/(sr·m²), flux W per linear-RGB channel.
//
// The rule (splitAreaLights, docs/renderer.md "Area lights"):
//   1. triangles of one instance and one material that share an edge (both ends within 0.1 mm
//      in world space) are connected; nothing else ever joins: separate panels in one merged
//      mesh become separate lights, and two instances never share a light (either may move);
//   2. a connected set is grown into nearly planar pieces from its first unassigned triangle
//      (in mesh order): a neighbour joins while its normal is within `planarDegrees` of the seed
//      triangle's, so a curved emitter (a tube, a dome) becomes strips or patches that each face
//      one way;
//   3. a piece longer than `maxExtent` along either of its in-plane principal axes is cut, on a
//      grid of equal cells along those axes, into cells no longer than that (triangles straddling
//      a cut are clipped), so a long strip is a row of lights whose centres stay near their
//      receivers (one shadow origin per light, one visibility per light and texel).
// A single quad stays one light. Every piece keeps its triangles' exact geometry: the pieces
// tile the emitters, so their summed unshadowed irradiance equals that of the original mesh.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

// One emissive triangle in world space.
struct EmitterTriangle {
  glm::vec3 v0, v1, v2;  // world, metres, counter-clockwise = the emitting front face
  glm::vec3 radiance;    // W/(sr·m²)
  bool doubleSided = false;
  uint32_t instance = 0;    // Scene::instances index
  uint32_t material = 0;    // Scene::materials index
  bool bakeDirect = false;  // Material::bakeDirect: its direct light is in the lightmap
};

struct AreaLight {
  uint32_t first = 0, count = 0;  // its triangles: AreaLightSet::triangles[first, first + count)
  uint32_t instance = 0, material = 0;
  Mobility mobility = Mobility::Static;  // its instance's: a static light's visibility is baked
  glm::vec3 centre{0.0f};                // area-weighted centroid, metres
  glm::vec3 normal{0.0f};  // unit area-weighted front normal; 0 when the faces cancel (closed)
  float area = 0.0f;       // m²
  float radius = 0.0f;     // largest distance of a vertex from the centre, metres
  glm::vec3 flux{0.0f};    // W emitted: Σ π·L·A (×2 when double-sided)
  bool doubleSided = false;
  // Its material's Material::bakeDirect: with a bake, its direct light is in the lightmap and the
  // renderer skips it; the baker bakes no visibility for it (it keeps its index).
  bool bakeDirect = false;
};

// The lights and their triangles, each light's contiguous. Static lights come first (in
// instance order), then the dynamic ones: the index of a static light never depends on where a
// dynamic instance stands, so a bake can name static lights by index.
struct AreaLightSet {
  std::vector<EmitterTriangle> triangles;
  std::vector<float> cumulativeArea;  // per triangle: its light's area up to and with it, m²
  std::vector<AreaLight> lights;
  std::size_t staticCount() const;
};

struct AreaLightRule {
  float planarDegrees = 15.0f;  // most a piece's triangle normals turn from its seed's
  float maxExtent = 1.5f;       // metres: longest a piece may be along an in-plane axis
};

// The emissive triangles of `scene` in world space (scene/surface_rules.h decides which emit),
// each instance at transforms[i] (object → world) or, when `transforms` is empty, at its own
// transform; mirrored instances have their winding flipped so the front face keeps emitting.
std::vector<EmitterTriangle> emitterTriangles(const Scene& scene,
                                              std::span<const glm::mat4> transforms = {});

// The lights of `triangles` by the rule above. `mobility[i]` is instance i's (missing: static).
AreaLightSet splitAreaLights(const std::vector<EmitterTriangle>& triangles,
                             std::span<const Mobility> mobility = {},
                             const AreaLightRule& rule = {});

// emitterTriangles then splitAreaLights with the scene's own mobility.
AreaLightSet sceneAreaLights(const Scene& scene, std::span<const glm::mat4> transforms = {},
                             const AreaLightRule& rule = {});

// The lights given a shadow map: at most `maxShadowed`, the largest total flux first (ties: the
// earlier light); returns their indices into `lights`, in that order.
std::vector<uint32_t> pickShadowedAreaLights(const std::vector<AreaLight>& lights, int maxShadowed);

// `count` points spread evenly over light `light` of `set` (a Hammersley set mapped onto its
// triangles by area), world metres: each stands for an equal share of the light's area.
std::vector<glm::vec3> samplePoints(const AreaLightSet& set, std::size_t light, int count);

// A point on light `light` of `set` for u in [0,1)²: u.x picks the triangle by area and is
// reused within it, u.y the second coordinate; uniform by area over the light.
glm::vec3 pointOnLight(const AreaLightSet& set, std::size_t light, glm::vec2 u);

}  // namespace bounce
