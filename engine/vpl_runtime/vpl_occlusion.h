// Which VPLs of a bake survive when dynamic objects are placed in the scene (GL-free).
//
// A VPL set is a set of light-path prefixes (bake_folder/vpl.h: each VPL knows where its incoming
// segment started and which path it ends; a path's VPLs are consecutive, in bounce order). The
// bake traced the paths in the static scene. An object placed later blocks a path where one of
// its segments (from → position) crosses the object's triangles: that VPL and every later VPL
// of the path were never reached, so their flux is 0. What remains is exactly the set the
// generator would have produced with the object as an occluder, for the same random numbers up
// to the blocked segment: an unbiased estimate of the indirect light of the static surfaces
// with the object present. What it still lacks: the light the object itself reflects (paths
// that would have bounced off it), second order for the object's own indirect light
// (docs/vpl.md, "Dynamic objects").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bake_folder/vpl.h"
#include "scene/scene.h"

namespace bounce {

// One placed object's world triangles (3 corners each, metres) and its bounding sphere.
struct VplOccluder {
  std::vector<glm::vec3> corners;
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};

VplOccluder makeVplOccluder(const Mesh& mesh, const glm::mat4& objectToWorld);
// The scene's dynamic instances (Mobility::Dynamic) at their current transforms.
std::vector<VplOccluder> dynamicVplOccluders(const Scene& scene);

// Per VPL 1 (alive) or 0 (its path was blocked at its segment or an earlier one). `vpls` in
// file order (path indices non-decreasing). A segment counts as blocked when it crosses a
// triangle strictly between its ends (parameter in (ε, 1 − ε), ε = 1e-4).
std::vector<uint8_t> vplAliveMask(std::span<const Vpl> vpls,
                                  std::span<const VplOccluder> occluders);

}  // namespace bounce
