// How a surface of the scene is read: the one place where the renderer (engine/render) and the
// path tracer (baker/trace) must agree, so both call these and neither has its own variant.
//   - which surfaces emit, and what: emittedRadiance / isEmitterTriangle;
//   - the reflectance a material really has: reflectance;
//   - what a material index out of range means: materialOf (an absorber: black, no emission);
//   - the shading normal where a mesh's is unusable: shadingNormalOr (the geometric normal).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

// Emitted radiance Le, W/(sr·m²) per channel: Material::emission, except that a material whose
// emission has any non-finite channel does not emit at all (0), and negative channels are 0.
glm::vec3 emittedRadiance(const Material& material);

// Diffuse reflectance ρ actually used: Material::albedo clamped to [0,1] (energy conserving,
// bounded path weights); any non-finite channel makes the surface black (absorbing).
glm::vec3 reflectance(const Material& material);

// A triangle emits when its material's emittedRadiance is positive in some channel and its
// area is positive and finite (`cross` = (p1−p0)×(p2−p0) in world space, |cross| = 2·area):
// a zero-area emitter gives no light and has no plane to face.
bool isEmitterTriangle(const Material& material, glm::vec3 cross);

// The material of triangles whose mesh names material `index`: Scene::materials[index], or,
// when out of range, an absorber (ρ = 0, no emission, single-sided) that casts shadows and
// shows black: a broken reference never borrows another material's colour or light.
const Material& materialOf(const Scene& scene, uint32_t index);

// A shading normal `n` (one corner's, or an interpolation) that is zero, non-finite or
// numerically degenerate (|n| ≤ 1e-6) is replaced by `geometric` (the triangle's unit normal);
// otherwise returns n normalized.
glm::vec3 shadingNormalOr(glm::vec3 n, glm::vec3 geometric);

}  // namespace bounce
