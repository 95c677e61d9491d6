// The outline of a planar area light: the boundary of the union of its triangles, one simple
// loop, counter-clockwise about the light's front normal. Lambert's contour integral over a
// polygon is additive: the triangles' integrals sum to the integral over the union's boundary
// (each interior edge is walked once each way and cancels), also after clipping every triangle
// by the same receiver horizon (the clipped pieces still share their interior edges). So one
// loop of k edges gives the exact irradiance a light of many coplanar triangles gives, at k edge
// terms instead of three per triangle: a rectangular panel of two triangles, 4 instead of 6.
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <vector>

#include "scene/area_lights.h"

namespace bounce {

// Light `light` of `set`'s outline, its corners in world metres, collinear corners dropped; none
// when its triangles are not one plane (all corners within 1e-5 of its size from the plane, and
// every front normal the light's), differ in radiance or sidedness, or do not meet edge to edge
// as one loop (a hole, two separate pieces, a T-junction), or the loop has more than
// `maxCorners` corners: then the triangles are evaluated one by one.
std::optional<std::vector<glm::vec3>> areaLightOutline(const AreaLightSet& set,
                                                       const AreaLight& light,
                                                       std::size_t maxCorners = 16);

}  // namespace bounce
