// Keeps light from leaking through geometry into a texel (and darkness out of it).
//
// Two ways a texel's sample points go wrong, both tested once per point before any light is
// gathered:
//   * inside geometry: a point under a block resting on the floor, or inside a wall thinner
//     than a texel, sees the back faces of single-sided triangles around it (not those of an
//     emitter that is an open sheet: a point behind it is in the seen, dark slot between a
//     ceiling and the panel hung under it, not inside anything). `probeRays` fixed
//     cosine-distributed rays leave each point; when at least `insideFraction` of them first hit
//     a back face, the point is dropped;
//   * across a wall: a texel straddling a thin wall has points on both sides. The texel keeps
//     the side of its representative point (the remaining point nearest the texel centre) and
//     drops every point that cannot see it (a shadow ray between the two, each lifted
//     `liftTexels` texel edges off its surface so that the chord of a curved surface does not
//     count as a wall).
// A covered texel left with no point is invalid: it gets its value from valid neighbours
// (dilation, lightmap_filters.h).
#pragma once

#include <cstdint>
#include <vector>

namespace bounce {

class RayKernel;
struct Scene;
struct TexelCoverage;
struct WorldGeometry;

struct LeakGuardSettings {
  int probeRays = 16;
  float insideFraction = 0.25f;
  float liftTexels = 0.25f;
  bool dropAcrossWalls = true;  // the representative-visibility test
  int threads = 0;              // 0: all cores
};

struct LeakGuardResult {
  std::vector<uint8_t> invalid;  // per texel: covered but every point was dropped
  uint64_t pointsInside = 0;     // dropped as inside geometry
  uint64_t pointsAcross = 0;     // dropped as across a wall from the representative
  uint64_t rays = 0;             // probe and visibility rays traced
};

// Drops the bad points from `coverage` (its point lists shrink in place).
LeakGuardResult guardAgainstLeaks(const Scene& scene, const WorldGeometry& geometry,
                                  const RayKernel& kernel, float texelSizeMetres,
                                  const LeakGuardSettings& settings, TexelCoverage& coverage);

}  // namespace bounce
