// No leaks: light does not pass a wall thinner than a texel, the dark inside of a block resting on
// the floor does not darken the floor around it, and the dark slot above a lamp hung under the
// ceiling is not lit from the ceiling around it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "bake_scenes.h"
#include "trace/path_tracer.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

// Two rooms side by side, x ∈ [0, 2], separated by a wall 2 cm thick at x ∈ [1.02, 1.04]
// (a fifth of a 10 cm texel, inside the floor's texel row [1.0, 1.1]); floor, ceiling and the
// long walls run through both rooms. A light hangs in room A (x < 1) only. Room B receives no
// light at all, so every texel whose centre lies in it must be exactly 0, with the denoiser
// too (it must not blur room A's light across the wall within the floor's chart).
TEST(Leaks, NoLightThroughAWallThinnerThanATexel) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.8f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(20.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {2, 1, 1}, white);
  // The wall: two single-sided faces looking out of it, closed by floor, ceiling and walls.
  test::addQuad(world.scene, {1.02f, 0, 0}, {1.02f, 0, 1}, {1.02f, 1, 1}, {1.02f, 1, 0}, white);
  test::addQuad(world.scene, {1.04f, 0, 0}, {1.04f, 1, 0}, {1.04f, 1, 1}, {1.04f, 0, 1}, white);
  test::addQuad(world.scene, {0.3f, 0.95f, 0.35f}, {0.6f, 0.95f, 0.35f}, {0.6f, 0.95f, 0.65f},
                {0.3f, 0.95f, 0.65f}, lamp);  // faces down
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.1f, 64);
  for (const bool denoise : {false, true}) {
    LightmapBakeSettings settings = test::testBakeSettings(32);
    settings.denoise = denoise;
    const LightmapBake bake =
        bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);
    int roomB = 0, litA = 0;
    for (int y = 0; y < atlas.layout.height; ++y) {
      for (int x = 0; x < atlas.layout.width; ++x) {
        const std::size_t t = bake.irradiance.index(x, y);
        glm::vec3 p;
        uint32_t instance;
        if (!bake.covered[t] || !atlas.texelCentre(x, y, p, instance) || instance >= 6) continue;
        if (p.x > 1.04f) {
          EXPECT_EQ(bake.irradiance.pixels[t], glm::vec3(0.0f))
              << "denoise " << denoise << ": room B texel (" << x << "," << y << ") at " << p.x
              << "," << p.y << "," << p.z;
          ++roomB;
        } else if (p.x < 1.0f && luminance(bake.irradiance.pixels[t]) > 0.0f) {
          ++litA;
        }
      }
    }
    EXPECT_GT(roomB, 150);  // floor, ceiling, far wall and both long walls' B halves
    EXPECT_GT(litA, 150);
    EXPECT_GT(bake.pointsAcross, 0u);
  }
}

// A closed room lit from the ceiling, a 30 cm block (five outward faces, no bottom) resting on
// the floor with its sides in the middle of 10 cm texels. Floor texels under the block are
// invalid and filled from the floor around; a texel straddling the block's foot holds the
// irradiance of its part outside the block, which an independent estimate (the tracer at
// uniformly random points of that part) gives. The lamp is a static area light: its baked
// visibility is filled under the block as the irradiance is.
TEST(Leaks, BlockOnTheFloorDoesNotDarkenTheFloorAroundIt) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.7f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(10.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {1, 1, 1}, white);  // instance 4: the floor
  const float lo = 0.35f, hi = 0.65f, top = 0.3f;
  auto face = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    test::addQuad(world.scene, a, b, c, d, white);
  };
  face({lo, 0, lo}, {lo, top, lo}, {hi, top, lo}, {hi, 0, lo});      // z = lo, faces −z
  face({lo, 0, hi}, {hi, 0, hi}, {hi, top, hi}, {lo, top, hi});      // z = hi, faces +z
  face({lo, 0, lo}, {lo, 0, hi}, {lo, top, hi}, {lo, top, lo});      // x = lo, faces −x
  face({hi, 0, lo}, {hi, top, lo}, {hi, top, hi}, {hi, 0, hi});      // x = hi, faces +x
  face({lo, top, lo}, {lo, top, hi}, {hi, top, hi}, {hi, top, lo});  // top, faces +y
  test::addQuad(world.scene, {0.3f, 0.95f, 0.3f}, {0.7f, 0.95f, 0.3f}, {0.7f, 0.95f, 0.7f},
                {0.3f, 0.95f, 0.7f}, lamp);
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.1f, 48);
  LightmapBakeSettings settings = test::testBakeSettings(512);
  settings.pointsPerTexel = 32;
  const LightmapBake bake =
      bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout, settings);

  TraceSettings trace;
  trace.paths = PathSet::IndirectOnly;
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, trace);
  auto under = [&](glm::vec3 p) { return p.x > lo && p.x < hi && p.z > lo && p.z < hi; };
  int straddling = 0, inside = 0;
  for (int y = 0; y < atlas.layout.height; ++y) {
    for (int x = 0; x < atlas.layout.width; ++x) {
      const std::size_t t = bake.irradiance.index(x, y);
      glm::vec3 c;
      uint32_t instance;
      if (!atlas.texelCentre(x, y, c, instance) || instance != 4) continue;
      // Texel square on the floor: centre ± 5 cm in x and z.
      const bool allUnder =
          under(c + glm::vec3(-0.049f, 0, -0.049f)) && under(c + glm::vec3(0.049f, 0, 0.049f));
      const bool someUnder = std::abs(c.x - 0.5f) < 0.2f && std::abs(c.z - 0.5f) < 0.2f;
      if (allUnder) {
        EXPECT_TRUE(bake.invalid[t]) << c.x << "," << c.z;
        EXPECT_GT(luminance(bake.irradiance.pixels[t]), 0.0f);  // filled from the floor around
        // Its baked visibility is filled the same way (the leak guard's verdict reaches the
        // visibility stage): it names the lamp, as every floor texel around it does, and holds a
        // 4-neighbour's record; an empty record would read as V = 1 (unshadowed) at the block's
        // foot, where bilinear filtering blends it in.
        ASSERT_TRUE(bake.visibility.has_value());
        const BakedVisibility& v = *bake.visibility;
        EXPECT_EQ(v.texels[t].light[0], 0u) << c.x << "," << c.z;
        bool fromNeighbour = false;
        for (const auto& [dx, dy] :
             {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
          const TexelVisibility& n = v.texels[bake.irradiance.index(x + dx, y + dy)];
          fromNeighbour |= n.light == v.texels[t].light && n.visible == v.texels[t].visible;
        }
        EXPECT_TRUE(fromNeighbour) << c.x << "," << c.z;
        ++inside;
        continue;
      }
      if (!someUnder) continue;
      // Independent reference: uniform points of the texel's outside part, many samples.
      SobolSampler sampler(1234, static_cast<uint32_t>(t));
      double sum = 0, sum2 = 0;
      const int n = 4096;
      for (int s = 0; s < n;) {
        sampler.startSample(static_cast<uint32_t>(s));
        const glm::vec2 u = sampler.get2D();
        const glm::vec3 p = c + glm::vec3(u.x - 0.5f, 0, u.y - 0.5f) * 0.1f;
        if (under(p)) {
          ++s;  // rejected; the sample index still advances
          sum += 0, sum2 += 0;
          continue;
        }
        const double e = luminance(tracer.irradiance(p, {0, 1, 0}, sampler));
        sum += e;
        sum2 += e * e;
        ++s;
      }
      // Mean over accepted points only: divide by the accepted count.
      int accepted = 0;
      for (int s = 0; s < n; ++s) {
        sampler.startSample(static_cast<uint32_t>(s));
        const glm::vec2 u = sampler.get2D();
        accepted += !under(c + glm::vec3(u.x - 0.5f, 0, u.y - 0.5f) * 0.1f);
      }
      const double mean = sum / accepted;
      const double variance = (sum2 / accepted - mean * mean) * accepted / (accepted - 1.0);
      const double seRef = std::sqrt(variance / accepted);
      const double e = luminance(bake.irradiance.pixels[t]);
      const double seBake = bake.relativeError[t] * e;
      EXPECT_FALSE(bake.invalid[t]);
      EXPECT_NEAR(e, mean, 5.0 * std::sqrt(seRef * seRef + seBake * seBake))
          << "straddling texel at " << c.x << "," << c.z;
      ++straddling;
    }
  }
  EXPECT_EQ(inside, 4);
  EXPECT_EQ(straddling, 12);
  EXPECT_GT(bake.pointsInside, 0u);
}

// A 40 cm lamp (one single-sided quad facing down, black behind) hangs 2 cm under the ceiling
// of a closed 1 m room, its edges on 10 cm texel lines. The ceiling above it is a surface the
// room sees through the 2 cm slot (the Conference Room's panels: a bright line there in the
// frame), lit only by what enters the slot at grazing angles. Most of the guard's probe rays
// from it meet the lamp's back: it must still keep its points (an emitter is a sheet, nothing
// is inside it), and its texels must hold the slot's own irradiance, which the tracer at
// uniformly random points of the lamp's footprint gives, not the lit ceiling's around it.
TEST(Leaks, TheSlotAboveALampUnderTheCeilingKeepsItsOwnDarkIrradiance) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.7f));
  const uint32_t lamp = test::addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(10.0f));
  test::addInwardBox(world.scene, {0, 0, 0}, {1, 1, 1}, white);  // instance 5: the ceiling
  const float lo = 0.3f, hi = 0.7f, y = 0.98f;
  test::addQuad(world.scene, {lo, y, lo}, {hi, y, lo}, {hi, y, hi}, {lo, y, hi}, lamp);
  world.build();
  const test::QuadAtlas atlas = test::quadAtlas(world.scene, 0.1f, 48);
  const LightmapBake bake = bakeLightmap(world.scene, world.geometry, *world.kernel, atlas.layout,
                                         test::testBakeSettings(256));

  // The bake: the mean over the 16 texels above the lamp (they tile its footprint), and over
  // the ceiling texels 15 cm or more from it.
  double slot = 0, slotVariance = 0, lit = 0;
  int slotTexels = 0, litTexels = 0;
  for (int ty = 0; ty < atlas.layout.height; ++ty) {
    for (int tx = 0; tx < atlas.layout.width; ++tx) {
      const std::size_t t = bake.irradiance.index(tx, ty);
      glm::vec3 c;
      uint32_t instance;
      if (!atlas.texelCentre(tx, ty, c, instance) || instance != 5) continue;
      const double e = luminance(bake.irradiance.pixels[t]);
      const float outside = std::max(std::abs(c.x - 0.5f), std::abs(c.z - 0.5f)) - 0.2f;
      if (outside < 0.0f) {
        EXPECT_FALSE(bake.invalid[t]) << "slot texel at " << c.x << "," << c.z;
        slot += e;
        slotVariance += std::pow(bake.relativeError[t] * e, 2.0);
        ++slotTexels;
      } else if (outside >= 0.15f) {
        lit += e;
        ++litTexels;
      }
    }
  }
  ASSERT_EQ(slotTexels, 16);
  ASSERT_GT(litTexels, 0);
  slot /= slotTexels;
  lit /= litTexels;
  const double seBake = std::sqrt(slotVariance) / slotTexels;

  // The reference: light that reflected at least once (what the lightmap holds) at uniformly
  // random points of the footprint on the ceiling, facing down.
  TraceSettings trace;
  trace.paths = PathSet::IndirectOnly;
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, trace);
  SobolSampler sampler(4321, 0);
  const int n = 4096;
  double sum = 0, sum2 = 0;
  for (int s = 0; s < n; ++s) {
    sampler.startSample(static_cast<uint32_t>(s));
    const glm::vec2 u = sampler.get2D();
    const glm::vec3 p(lo + (hi - lo) * u.x, 1.0f, lo + (hi - lo) * u.y);
    const double e = luminance(tracer.irradiance(p, {0, -1, 0}, sampler));
    sum += e;
    sum2 += e * e;
  }
  const double ref = sum / n;
  const double seRef = std::sqrt(std::max(0.0, sum2 / n - ref * ref) / (n - 1));
  EXPECT_NEAR(slot, ref, 5.0 * std::hypot(seRef, seBake)) << "lit ceiling " << lit;
  // The slot sees the room through 2 cm at most 20 cm away: a small part of its hemisphere.
  EXPECT_LT(slot, 0.25 * lit);
}

}  // namespace
}  // namespace bounce
