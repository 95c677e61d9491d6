// Scenes and lightmap layouts for the baker's tests, built in code apart from the atlas: every
// instance is one rectangle (tests/trace/test_scenes.h addQuad) laid out by hand, so a texel's
// world position is known exactly.
#pragma once

#include <numbers>
#include <vector>

#include <glm/glm.hpp>

#include "bake/lightmap_bake.h"
#include "bake_folder/lightmap_layout.h"
#include "test_scenes.h"

namespace bounce::test {

// Where a rectangle instance lies in the atlas: texel-space point t maps to the world point
// corner + (t − origin).x · texelSize · uAxis + (t − origin).y · texelSize · vAxis.
struct QuadChart {
  uint32_t instance = 0;
  glm::vec2 origin{0.0f};  // texel space
  glm::vec3 corner{0.0f}, uAxis{0.0f}, vAxis{0.0f};
  glm::vec2 extent{0.0f};  // texels
};

struct QuadAtlas {
  LightmapLayout layout;
  std::vector<QuadChart> charts;
  // World point of texel (x, y)'s centre, or false when no chart's rectangle holds it.
  bool texelCentre(int x, int y, glm::vec3& world, uint32_t& instance) const;
};

// Shelf-packs every rectangle instance (p0 p1 p2 p3 with indices 0 1 2 0 2 3; u along p1 − p0,
// v along p3 − p0) at `texelSize` metres per texel, `padding` texels apart, charts starting
// on whole texels, in an atlas `width` texels wide.
QuadAtlas quadAtlas(const Scene& scene, float texelSize, int width = 64, int padding = 2);

// The closed furnace: a 1 m box of albedo ρ whose every face emits Le (W/(sr·m²)), seen from
// inside. The radiance is Le/(1 − ρ) everywhere, so the irradiance from light that reflected at
// least once (what the lightmap holds) is π·Le·ρ/(1 − ρ) at every point. Built in place (a built
// World must not move).
struct ClosedFurnace {
  float rho, le;
  World world;
  ClosedFurnace(float albedo, float emitted) : rho(albedo), le(emitted) {
    const uint32_t m = addMaterial(world.scene, glm::vec3(rho), glm::vec3(le));
    addInwardBox(world.scene, glm::vec3(0.0f), glm::vec3(1.0f), m);
    world.build();
  }
  double exactIndirectIrradiance() const {  // W/m²
    return std::numbers::pi * le * rho / (1.0 - rho);
  }
};

// Two bakes of one map are the same bytes: the irradiance bit for bit and the same samples per
// texel (the determinism tests: thread counts, tile sizes).
void expectSameLightmap(const LightmapBake& a, const LightmapBake& b);

// A 1 m room lit by a small lamp in one corner of the ceiling, with a board casting shadow:
// texels near the lamp are bright, the far corners under the board dim (≈ 50× apart).
void buildCornerLampRoom(World& world);

// A default bake with `threads`, fixed spp, no denoiser.
LightmapBakeSettings testBakeSettings(int spp, uint32_t seed = 7, int threads = 0);

}  // namespace bounce::test
