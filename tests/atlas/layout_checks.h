// Checks of an atlas that every test applies: what is wrong with it, in words, or "" when nothing.
#pragma once

#include <string>

#include "atlas/atlas.h"
#include "scene/scene.h"

namespace bounce::test {

// Every static instance with triangles has a region with 3 UVs per triangle inside [0,1]², and
// no dynamic one has; UVs are finite; every chart id is below chartCount.
std::string regionProblem(const Scene& scene, const Atlas& atlas);
// No two triangles of one chart overlap (exact 2D test, tolerance 1e-3 texel); no texel touched
// by one chart is within `padding` texels (Chebyshev distance) of a texel touched by another.
std::string overlapProblem(const Atlas& atlas);
// Covered texels (touched by any triangle) / atlas texels, recounted here.
double recountUtilisation(const Atlas& atlas);

}  // namespace bounce::test
