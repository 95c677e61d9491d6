// Next-event estimation picking its light by place (trace/light_sampler.h pickAt): unbiased with
// every kind of light and emitter clusters, under each strategy (the BRDF-hit MIS weight must use
// the pmf of the cluster picked at the previous vertex), against closed forms; and the reason it
// exists, a lower variance where one near light sits among far, powerful ones. Tolerances are 5
// standard errors estimated from the samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "support/form_factors.h"
#include "test_scenes.h"

namespace bounce {
namespace {

using test::addMaterial;
using test::addQuad;
using test::planeWorld;

constexpr double kPiD = std::numbers::pi;

struct Square {
  double x0, x1, y0, y1;  // at z = kEmitterHeight, facing down
  glm::dvec3 le;          // W/(sr·m²)
};
constexpr double kEmitterHeight = 1.0;

// Eight unequal emitter squares in a row at 1 m (so the sampler makes clusters of them), and
// lights of each punctual kind above them, one spot tilted.
std::vector<Square> eightSquares() {
  std::vector<Square> squares;
  for (int i = 0; i < 8; ++i) {
    const double x = -3.2 + 0.8 * i, s = 0.25 + 0.05 * (i % 3);
    const double k = 1.0 + 3.0 * ((i * 5) % 8);
    squares.push_back({x, x + s, -0.2, -0.2 + s, glm::dvec3(k, 0.8 * k, 0.5 * k + 1.0)});
  }
  return squares;
}

std::vector<Light> punctualLights() {
  std::vector<Light> lights;
  for (int i = 0; i < 6; ++i) {
    Light l;
    l.type = LightType::Point;
    l.position =
        glm::vec3(-4.0f + 1.7f * static_cast<float>(i), 0.9f - 0.3f * static_cast<float>(i),
                  0.4f + 0.5f * static_cast<float>(i % 3));
    l.intensity = glm::vec3(2.0f + 9.0f * static_cast<float>(i % 4));
    lights.push_back(l);
  }
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {1.0f, -1.5f, 2.5f};
  spot.direction = glm::normalize(glm::vec3(0.4f, 0.3f, -1.0f));
  spot.intensity = {60, 50, 30};
  spot.innerConeAngle = 0.2f;
  spot.outerConeAngle = 0.6f;
  lights.push_back(spot);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.5f, -0.2f, -1.0f));
  sun.irradiance = {0.4f, 0.3f, 0.2f};
  lights.push_back(sun);
  return lights;
}

// Whether the segment from x (on the plane) towards `to` (or along direction `away` to infinity)
// crosses one of the squares at z = 1.
bool shadowedBySquares(const std::vector<Square>& squares, glm::dvec3 x, glm::dvec3 away) {
  if (away.z <= 0.0) return false;
  const double t = (kEmitterHeight - x.z) / away.z;
  if (t >= 1.0) return false;  // `away` ends below the squares
  const glm::dvec3 c = x + away * t;
  for (const Square& s : squares) {
    if (c.x >= s.x0 && c.x <= s.x1 && c.y >= s.y0 && c.y <= s.y1) return true;
  }
  return false;
}

glm::dvec3 exactIrradiance(const std::vector<Square>& squares, const std::vector<Light>& lights,
                           glm::dvec3 x) {
  glm::dvec3 e(0.0);
  for (const Square& s : squares) {
    e += kPiD * s.le *
         test::parallelRectangleFormFactor(x.x, x.y, s.x0, s.x1, s.y0, s.y1, kEmitterHeight);
  }
  for (const Light& l : lights) {
    if (l.type == LightType::Directional) {
      const glm::dvec3 w = -glm::normalize(glm::dvec3(l.direction));
      if (!shadowedBySquares(squares, x, w * 1e6)) e += glm::dvec3(l.irradiance) * w.z;
      continue;
    }
    if (!shadowedBySquares(squares, x, glm::dvec3(l.position) - x))
      e += test::punctualIrradiance(l, x);
  }
  return e;
}

test::World squaresAndLights(const std::vector<Square>& squares) {
  test::World world = planeWorld(glm::vec3(0.5f));  // albedo irrelevant: E is measured
  for (const Square& s : squares) {
    const auto x0 = static_cast<float>(s.x0), x1 = static_cast<float>(s.x1);
    const auto y0 = static_cast<float>(s.y0), y1 = static_cast<float>(s.y1);
    const auto z = static_cast<float>(kEmitterHeight);
    // Facing down (−z): counter-clockwise seen from below.
    addQuad(world.scene, {x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z},
            addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(s.le)));
  }
  world.scene.lights = punctualLights();
  world.build();
  return world;
}

TEST(LightChoice, ByPlaceIsExactWithEveryKindAndEmitterClustersUnderEachStrategy) {
  const std::vector<Square> squares = eightSquares();
  const test::World world = squaresAndLights(squares);
  const glm::dvec3 points[] = {{-2.3, -0.1, 0.0}, {0.3, 0.5, 0.0}, {2.0, -1.0, 0.0}};
  for (LightStrategy strategy :
       {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
    TraceSettings settings;
    settings.strategy = strategy;
    settings.paths = PathSet::DirectOnly;
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    ASSERT_TRUE(tracer.lightSampler().choosesByPlace());
    ASSERT_GT(tracer.emitters().clusters().size(), 4u);
    for (const glm::dvec3& x : points) {
      // BrdfOnly finds the squares by BRDF sampling alone; delta lights are always sampled.
      const glm::dvec3 exact = exactIrradiance(squares, world.scene.lights, x);
      const test::Estimate e =
          test::estimateIrradiance(tracer, glm::vec3(x), {0, 0, 1}, 13u, 5u, 16384);
      std::printf("by place, strategy %d at (%.1f, %.1f): E = %.5f ± %.5f, exact %.5f W/m²\n",
                  static_cast<int>(strategy), x.x, x.y, e.mean.g, e.standardError().g, exact.g);
      EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), exact, glm::dvec3(0.0), 5.0))
          << "strategy " << static_cast<int>(strategy);
    }
  }
}

// A 1 W/sr lamp 0.5 m over the point and 20 lamps of 100 W/sr 10 m away: by power the near one
// is picked once in ~2000 (E is a rare large value), by place most of the time.
TEST(LightChoice, ANearLampAmongFarPowerfulOnesHasLessVarianceByPlace) {
  test::World world = planeWorld(glm::vec3(0.5f));
  Light near;
  near.position = {0.0f, 0.0f, 0.5f};
  near.intensity = glm::vec3(1.0f);
  world.scene.lights.push_back(near);
  for (int i = 0; i < 20; ++i) {
    Light far;
    const double a = 2.0 * kPiD * i / 20.0;
    far.position = glm::vec3(static_cast<float>(10.0 * std::cos(a)),
                             static_cast<float>(10.0 * std::sin(a)), 1.0f);
    far.intensity = glm::vec3(100.0f);
    world.scene.lights.push_back(far);
  }
  world.build();
  glm::dvec3 exact(4.0);  // I/d² from the near lamp
  for (std::size_t i = 1; i < world.scene.lights.size(); ++i) {
    const glm::dvec3 d = glm::dvec3(world.scene.lights[i].position);
    exact += 100.0 * d.z / std::pow(glm::dot(d, d), 1.5);
  }
  double variance[2] = {0.0, 0.0};
  for (LightChoice choice : {LightChoice::ByPlace, LightChoice::ByPower}) {
    TraceSettings settings;
    settings.paths = PathSet::DirectOnly;
    settings.lightChoice = choice;
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    const test::Estimate e = test::estimateIrradiance(tracer, {0, 0, 0}, {0, 0, 1}, 3u, 1u, 65536);
    EXPECT_TRUE(test::agreeWithin(e.mean, e.standardError(), exact, glm::dvec3(0.0), 5.0));
    variance[choice == LightChoice::ByPlace ? 0 : 1] = e.variance.g;
    std::printf("%s: E = %.4f ± %.4f (exact %.4f), variance per sample %.3g\n",
                choice == LightChoice::ByPlace ? "by place" : "by power", e.mean.g,
                e.standardError().g, exact.g, e.variance.g);
  }
  // Weights by place: 4 W/m² for the near lamp, about 1 for each far one, so it is picked with
  // p ≈ 0.9·4/24 ≈ 0.15 and the variance is ≈ 4²/0.15 − E² ≈ 70; by power, p ≈ 1/2001 and
  // ≈ 4²·2001 ≈ 3.2e4. Ask for a factor 100.
  EXPECT_LT(variance[0] * 100.0, variance[1]);
}

}  // namespace
}  // namespace bounce
