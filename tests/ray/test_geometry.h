// Procedural triangle scenes and ray sets for the ray-kernel tests and benchmarks: closed
// meshes (cube, icosphere), random triangle soups, displaced spheres, and both coherent
// (pinhole camera) and incoherent (cosine-weighted from random surface points) rays.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "ray/ray_kernel.h"
#include "scene/world_geometry.h"

namespace bounce::testing {

// Appends a closed mesh to `g` with outward-facing counter-clockwise triangles.
void addCube(WorldGeometry& g, const glm::mat4& transform);  // the [-1,1]³ cube, 12 triangles
void addIcosphere(WorldGeometry& g, int subdivisions, glm::vec3 centre, float radius);
// A closed sphere of `rings`×`segments` quads whose radius varies by ±`bumpiness` with a smooth
// pseudo-random field: the dense "scanned object" of the benchmarks.
void addDisplacedSphere(WorldGeometry& g, int rings, int segments, glm::vec3 centre, float radius,
                        float bumpiness, uint32_t seed);
// `count` random triangles with vertices in [lower, upper], edge lengths up to maxEdge.
void addTriangleSoup(WorldGeometry& g, int count, glm::vec3 lower, glm::vec3 upper, float maxEdge,
                     uint32_t seed);

// Fills the per-triangle/per-vertex arrays that flatten() would (materials, instances,
// normals, UVs) so the geometry is complete.
void finish(WorldGeometry& g);

// Pinhole camera rays over a width×height image from `eye` towards `target` (60° fov),
// in scanline order: neighbours are coherent.
std::vector<Ray> cameraRays(glm::vec3 eye, glm::vec3 target, int width, int height);

// Rays leaving uniformly chosen points on random non-degenerate triangles, cosine-distributed
// about the geometric normal on a random side, origins moved off the surface with
// offsetRayOrigin. tmax = ∞, or uniform in (0, maxDistance] when maxDistance > 0 (shadow-ray
// style queries). Shuffled: consecutive rays are unrelated.
std::vector<Ray> surfaceRays(const WorldGeometry& g, std::size_t count, uint32_t seed,
                             float maxDistance = 0.0f);

// Cosine-weighted direction about unit n from two uniform numbers in [0,1).
glm::vec3 cosineDirection(glm::vec3 n, float u1, float u2);

}  // namespace bounce::testing
