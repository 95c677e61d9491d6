// Scenes that make plausible estimator bugs visible where the square-over-a-parallel-plane
// tests cannot: emitters of unequal area and radiance (the emitter-selection pmf must agree
// with the pdf in the MIS weight), emitters perpendicular or tilted 45° to their receivers
// (the cosine at the emitter and the cosine at the receiver differ) and surfaces with smooth
// normals (a light's cosine belongs to the shading normal, its horizon to the geometric one,
// for delta and area lights). Each is checked through PathTracer::Li and, where it applies,
// through PathTracer::irradiance, the baker's entry point, against closed forms from
// tests/support, within 5 standard errors of the estimate (its sample variance) or float
// rounding where the estimator is deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "support/delta_light.h"
#include "support/form_factors.h"
#include "support/polygon_form_factor.h"
#include "test_scenes.h"

namespace bounce {
namespace {

using test::addMaterial;
using test::addQuad;
using test::downOnto;
using test::parallelRectangleFormFactor;
using test::perpendicularFormFactor;
using test::planeWorld;
using test::polygonFormFactor;

constexpr double kPiD = std::numbers::pi;
const glm::dvec3 kPlaneAlbedo(0.5, 0.7, 0.3);

// A rectangle [x0,x1]×[y0,y1] at height z whose front (the emitting face) faces −z.
void addDownwardRectangle(test::World& world, float x0, float x1, float y0, float y1, float z,
                          uint32_t material) {
  addQuad(world.scene, {x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z}, material);
}

const char* strategyName(LightStrategy s) {
  switch (s) {
    case LightStrategy::Mis:
      return "MIS";
    case LightStrategy::LightOnly:
      return "light-only";
    case LightStrategy::BrdfOnly:
      return "BRDF-only";
  }
  return "?";
}

// The estimate's mean within 5 of its standard errors of the closed form (per channel).
void expectMatches(const std::string& what, const test::Estimate& e, glm::dvec3 expected) {
  const glm::dvec3 se = e.standardError();
  std::printf("%s: %.5f expected %.5f (%+.2f%%, %+.1f SE)\n", what.c_str(), e.mean.g, expected.g,
              100.0 * (e.mean.g / expected.g - 1.0), (e.mean.g - expected.g) / se.g);
  EXPECT_TRUE(test::agreeWithin(e.mean, se, expected, glm::dvec3(0.0), 5.0)) << what;
}

// Two emitters of very different area and radiance over the plane: a small bright one
// (0.2 m × 0.2 m at 0.8 m, Le = (20, 10, 30)) and a large dim one (1 m × 2 m at 1.2 m,
// Le = (1, 2, 0.5)). Sampled by power, a triangle of the small one is picked with
// probability 0.070; by area it would be 0.0098, uniformly 0.25, so a pick pmf that
// disagrees with the density in the MIS weight (or with the one NEE divides by) moves the
// estimate. The plane reflects Lo = ρ·Σ Le_i·F_i and a point on it receives E = π·Σ Le_i·F_i,
// F_i the closed-form parallel-rectangle form factors (the emitters do not shadow each other
// and are black, and light leaving the plane escapes).
TEST(BlindSpots, UnequalEmittersMatchTheirFormFactors) {
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
  const glm::dvec3 bright(20, 10, 30), dim(1, 2, 0.5);
  addDownwardRectangle(world, 0.2f, 0.4f, -0.1f, 0.1f, 0.8f,
                       addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(bright)));
  addDownwardRectangle(world, -1.5f, -0.5f, -1.0f, 1.0f, 1.2f,
                       addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(dim)));
  world.build();
  uint32_t pattern = 200;
  for (glm::dvec2 at : {glm::dvec2(0.3, 0.0), glm::dvec2(-0.2, 0.4), glm::dvec2(-1.1, -0.3)}) {
    const glm::dvec3 sumLeF =
        bright * parallelRectangleFormFactor(at.x, at.y, 0.2, 0.4, -0.1, 0.1, 0.8) +
        dim * parallelRectangleFormFactor(at.x, at.y, -1.5, -0.5, -1.0, 1.0, 1.2);
    for (LightStrategy strategy :
         {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
      TraceSettings settings;
      settings.strategy = strategy;
      const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
      const std::string where = std::string(strategyName(strategy)) + " at (" +
                                std::to_string(at.x) + ", " + std::to_string(at.y) + ")";
      ++pattern;
      expectMatches("unequal emitters, Li " + where,
                    test::estimateLi(tracer, downOnto(at.x, at.y, 0.5f), pattern, pattern, 8192),
                    kPlaneAlbedo * sumLeF);
      ++pattern;
      const glm::vec3 p(static_cast<float>(at.x), static_cast<float>(at.y), 0.0f);
      expectMatches("unequal emitters, irradiance " + where,
                    test::estimateIrradiance(tracer, p, {0, 0, 1}, pattern, pattern, 8192),
                    kPiD * sumLeF);
    }
  }
}

// An emitter standing perpendicular to the receiving plane, the wall x = 1 m facing −x over
// y ∈ [y0, y1], z ∈ [z0, z1]. Seen from a plane point, the cosine at the receiver (z/r) and at
// the emitter (Δx/r) differ everywhere, unlike over a parallel emitter where they are equal;
// swapping them (in the solid-angle pdf, in the contribution or in the MIS weight of BRDF
// hits) moves the estimate. Closed form: the perpendicular-rectangle form factor, summed over
// the two sides of the receiver's foot and differenced over height:
// F = Σ_{W ∈ {y − y0, y1 − y}} F⊥(d, z1, W) − F⊥(d, z0, W), d = 1 − x.
// Two walls: a 1.1 m × 1 m one (light sampling carries the MIS estimate) and a 6 m × 3 m one
// with receivers 5–20 cm from its foot, where BRDF hits carry much of it (p_brdf = z/(π·r)
// against p_light = r³/(A·d)), so a wrong cosine in their MIS weight shows (it moves MIS by
// 7–11%; 32768 samples keep MIS's standard error near 0.6%).
struct Wall {
  float y0, y1, z0, z1;
  std::vector<glm::dvec2> receivers;
  int samples;
};

TEST(BlindSpots, PerpendicularEmitterMatchesItsFormFactor) {
  const glm::dvec3 le(3, 4, 5);
  uint32_t pattern = 300;
  const Wall walls[] = {{-0.4f, 0.7f, 0.2f, 1.2f, {{0.0, 0.0}, {0.6, 0.1}, {-0.5, 0.5}}, 8192},
                        {-3.0f, 3.0f, 0.0f, 3.0f, {{0.8, 0.3}, {0.95, -1.0}}, 32768}};
  for (const Wall& wall : walls) {
    test::World world = planeWorld(glm::vec3(kPlaneAlbedo));
    const uint32_t light = addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(le));
    // Counter-clockwise seen from −x: the front faces −x, towards the receivers.
    addQuad(world.scene, {1, wall.y0, wall.z0}, {1, wall.y0, wall.z1}, {1, wall.y1, wall.z1},
            {1, wall.y1, wall.z0}, light);
    world.build();
    for (glm::dvec2 at : wall.receivers) {
      const double d = 1.0 - at.x;
      double f = 0.0;
      for (double w : {at.y - wall.y0, wall.y1 - at.y}) {
        f += perpendicularFormFactor(d, wall.z1, w) - perpendicularFormFactor(d, wall.z0, w);
      }
      for (LightStrategy strategy :
           {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
        TraceSettings settings;
        settings.strategy = strategy;
        const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
        const std::string where = std::string(strategyName(strategy)) + " at (" +
                                  std::to_string(at.x) + ", " + std::to_string(at.y) + ")";
        ++pattern;
        expectMatches(
            "perpendicular emitter, Li " + where,
            test::estimateLi(tracer, downOnto(at.x, at.y, 0.01f), pattern, pattern, wall.samples),
            kPlaneAlbedo * le * f);
        ++pattern;
        const glm::vec3 p(static_cast<float>(at.x), static_cast<float>(at.y), 0.0f);
        expectMatches(
            "perpendicular emitter, irradiance " + where,
            test::estimateIrradiance(tracer, p, {0, 0, 1}, pattern, pattern, wall.samples),
            kPiD * le * f);
      }
    }
  }
}

// Smooth normals: the plane's shading normal is tilted 30° towards +x from its geometric
// normal +z. A delta light reflects Lo = ρ/π·E⊥·max(0, n_s·ω) while it is above the geometric
// surface (tests/support/delta_light.h). The lights are placed so that n_s·ω and n_g·ω differ
// by 10–90% (and at x = 5 n_s·ω < 0 < n_g·ω: black). Deterministic (NEE only; bounce rays
// escape), so the tolerance is float rounding.
const glm::dvec3 kTiltedNormal(0.5, 0.0, std::sqrt(0.75));

void expectExactly(const std::string& what, const PathTracer& tracer, const Ray& ray,
                   glm::dvec3 expected) {
  const test::Estimate e = test::estimateLi(tracer, ray, 1u, 0u, 16);
  std::printf("%s: %.6f expected %.6f\n", what.c_str(), e.mean.g, expected.g);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(e.mean[c], expected[c], 1e-5 * std::abs(expected[c]) + 1e-9)
        << what << ", channel " << c;
    EXPECT_LE(e.variance[c], 1e-12) << what << ": a delta light's estimate has no variance";
  }
}

TEST(BlindSpots, DeltaLightCosineIsOnTheShadingNormal) {
  const glm::dvec3 up(0, 0, 1);
  {
    test::World world = planeWorld(glm::vec3(kPlaneAlbedo), glm::vec3(kTiltedNormal));
    Light light;
    light.type = LightType::Point;
    light.position = {0, 0, 2};
    light.intensity = {10, 20, 5};
    world.scene.lights.push_back(light);
    world.build();
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
    for (double x : {-1.0, 1.0, 2.5, 5.0}) {
      const glm::dvec3 expected = test::pointLightRadiance(
          kPlaneAlbedo, glm::dvec3(light.intensity), glm::dvec3(light.position),
          glm::dvec3(x, 0.3, 0.0), kTiltedNormal, up);
      expectExactly("point light, smooth normal, x = " + std::to_string(x), tracer,
                    downOnto(x, 0.3, 1.0f), expected);
    }
  }
  {
    test::World world = planeWorld(glm::vec3(kPlaneAlbedo), glm::vec3(kTiltedNormal));
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1, 0.3f, -2));
    sun.irradiance = {3, 2, 1};
    world.scene.lights.push_back(sun);
    world.build();
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
    const glm::dvec3 expected = test::lambertianRadiance(
        kPlaneAlbedo, glm::dvec3(sun.irradiance), -glm::dvec3(sun.direction), kTiltedNormal, up);
    expectExactly("directional light, smooth normal", tracer, downOnto(0.5, 0.5, 1.0f), expected);
  }
}

// The reverse: light from below the geometric surface but above the tilted shading normal's
// horizon (n_s·ω > 0 > n_g·ω) must not reach the surface, for a point and a directional light:
// the horizon belongs to the geometric normal.
TEST(BlindSpots, DeltaLightBelowTheGeometricSurfaceDoesNotLeak) {
  const glm::dvec3 toPoint(2.0, 0.0, -0.3);  // from the receiver at the origin
  const glm::dvec3 toSun = glm::normalize(glm::dvec3(1.0, 0.2, -0.2));
  ASSERT_GT(glm::dot(kTiltedNormal, toPoint), 0.0);
  ASSERT_GT(glm::dot(kTiltedNormal, toSun), 0.0);
  Light point;
  point.type = LightType::Point;
  point.position = glm::vec3(toPoint);
  point.intensity = {10, 20, 5};
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = -glm::vec3(toSun);
  sun.irradiance = {3, 2, 1};
  for (const Light& light : {point, sun}) {
    test::World world = planeWorld(glm::vec3(kPlaneAlbedo), glm::vec3(kTiltedNormal));
    world.scene.lights = {light};
    world.build();
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
    expectExactly(std::string(light.type == LightType::Point ? "point" : "directional") +
                      " light below the geometric surface",
                  tracer, downOnto(0.0, 0.0, 1.0f), glm::dvec3(0.0));
  }
}

// Irradiance (the baker's entry point) from light that reached a smooth-normal surface from a
// delta light: a 2 m × 2 m reflector at z = 1 m facing down (ρ = kPlaneAlbedo, shading normal
// tilted 30° off its geometric −z), lit from below by a directional light. Every point of it
// reflects the same radiance L_r = ρ/π·E⊥·max(0, n_s·ω), so a point at z = 0 facing up
// receives E = π·L_r·F (parallel-rectangle form factor). With the cosine on the geometric
// normal L_r would be 1.77× larger.
TEST(BlindSpots, IrradianceFromASmoothNormalReflector) {
  test::World world;
  const uint32_t m = addMaterial(world.scene, glm::vec3(kPlaneAlbedo));
  addDownwardRectangle(world, -1, 1, -1, 1, 1, m);
  const glm::dvec3 shading = glm::normalize(glm::dvec3(-0.5, 0.0, -std::sqrt(0.75)));
  world.scene.meshes.back().normals.assign(4, glm::vec3(shading));
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(-0.6f, 0, 1));  // travelling up
  sun.irradiance = {3, 2, 1};
  world.scene.lights.push_back(sun);
  world.build();
  const glm::dvec3 lr = test::lambertianRadiance(kPlaneAlbedo, glm::dvec3(sun.irradiance),
                                                 -glm::dvec3(sun.direction), shading, {0, 0, -1});
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, TraceSettings{});
  uint32_t pattern = 400;
  for (glm::dvec2 at : {glm::dvec2(0.3, 0.2), glm::dvec2(-0.8, 1.3)}) {
    const double f = parallelRectangleFormFactor(at.x, at.y, -1, 1, -1, 1, 1);
    ++pattern;
    const glm::vec3 p(static_cast<float>(at.x), static_cast<float>(at.y), 0.0f);
    expectMatches("smooth-normal reflector, irradiance at (" + std::to_string(at.x) + ", " +
                      std::to_string(at.y) + ")",
                  test::estimateIrradiance(tracer, p, {0, 0, 1}, pattern, pattern, 8192),
                  kPiD * lr * f);
  }
}

// Lambert's contour formula (tests/support/polygon_form_factor.h), the reference of the next
// tests, against the two rectangle closed forms it must reproduce.
TEST(BlindSpots, LambertsFormulaMatchesTheRectangleClosedForms) {
  const glm::dvec3 up(0, 0, 1);
  // The square [−0.5,0.5]² at height 1, counter-clockwise seen from below.
  const std::vector<glm::dvec3> square = {
      {-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}};
  for (glm::dvec2 at : {glm::dvec2(0, 0), glm::dvec2(0.4, 0.3), glm::dvec2(1.5, -0.2)}) {
    EXPECT_NEAR(polygonFormFactor(square, {at.x, at.y, 0}, up),
                parallelRectangleFormFactor(at.x, at.y, -0.5, 0.5, -0.5, 0.5, 1.0), 1e-12);
  }
  // The wall x = 1, y ∈ [−0.4, 0.7], z ∈ [0.2, 1.2], counter-clockwise seen from −x.
  const std::vector<glm::dvec3> wall = {
      {1, -0.4, 0.2}, {1, -0.4, 1.2}, {1, 0.7, 1.2}, {1, 0.7, 0.2}};
  for (glm::dvec2 at : {glm::dvec2(0, 0), glm::dvec2(0.6, 0.1)}) {
    double f = 0.0;
    for (double w : {at.y + 0.4, 0.7 - at.y}) {
      f += perpendicularFormFactor(1 - at.x, 1.2, w) - perpendicularFormFactor(1 - at.x, 0.2, w);
    }
    EXPECT_NEAR(polygonFormFactor(wall, {at.x, at.y, 0}, up), f, 1e-12);
  }
  // Clipping: the half of the square above y = 0 seen from (0, 0, 0) is half the square.
  EXPECT_NEAR(polygonFormFactor(test::clipPolygon(square, {0, 0, 0}, {0, 1, 0}), {0, 0, 0}, up),
              0.5 * parallelRectangleFormFactor(0, 0, -0.5, 0.5, -0.5, 0.5, 1.0), 1e-12);
}

// A 1 m × 0.6 m emitter tilted 45° (centre (1, 0, 1), facing (−1, 0, −1)/√2, Le = (3, 4, 5)):
// neither parallel nor perpendicular to its receivers. Its corners as floats, as the scene
// holds them, counter-clockwise seen from its front.
std::vector<glm::vec3> tiltedEmitterCorners() {
  const glm::vec3 c(1, 0, 1), a = 0.5f * glm::vec3(0.70710678f, 0, -0.70710678f), b(0, 0.3f, 0);
  return {c - a - b, c - a + b, c + a + b, c + a - b};
}

void addTiltedEmitter(test::World& world, glm::dvec3 le) {
  const std::vector<glm::vec3> p = tiltedEmitterCorners();
  addQuad(world.scene, p[0], p[1], p[2], p[3],
          addMaterial(world.scene, glm::vec3(0.0f), glm::vec3(le)));
}

// F of the tilted emitter seen from x with the cosine on `cosineNormal` and the horizon on
// `horizonNormal` (clipped by both planes); 0 behind it (it emits from its front only).
double tiltedEmitterFormFactor(glm::dvec3 x, glm::dvec3 cosineNormal, glm::dvec3 horizonNormal) {
  std::vector<glm::dvec3> polygon;
  for (glm::vec3 p : tiltedEmitterCorners()) polygon.emplace_back(p);
  const glm::dvec3 front = glm::cross(polygon[1] - polygon[0], polygon[2] - polygon[0]);
  if (glm::dot(front, x - polygon[0]) <= 0.0) return 0.0;
  polygon = test::clipPolygon(test::clipPolygon(polygon, x, horizonNormal), x, cosineNormal);
  return polygonFormFactor(polygon, x, cosineNormal);
}

// The tilted emitter through Li over a flat plane (Lo = ρ·Le·F) and through irradiance at
// points in empty space (no plane: E = π·Le·F), facing up, 30° towards +x and 51° towards −x
// (whose horizon cuts the emitter), each strategy, 8192 samples, 5 SE.
TEST(BlindSpots, TiltedEmitterMatchesLambertsFormula) {
  const glm::dvec3 le(3, 4, 5), up(0, 0, 1);
  test::World plane = planeWorld(glm::vec3(kPlaneAlbedo));
  addTiltedEmitter(plane, le);
  plane.build();
  test::World empty;
  addTiltedEmitter(empty, le);
  empty.build();
  uint32_t pattern = 600;
  for (LightStrategy strategy :
       {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
    TraceSettings settings;
    settings.strategy = strategy;
    const PathTracer onPlane(plane.scene, plane.geometry, *plane.kernel, settings);
    const PathTracer inSpace(empty.scene, empty.geometry, *empty.kernel, settings);
    for (glm::dvec2 at : {glm::dvec2(0.0, 0.0), glm::dvec2(0.5, -0.3), glm::dvec2(1.0, 1.2)}) {
      const std::string where = std::string(strategyName(strategy)) + " at (" +
                                std::to_string(at.x) + ", " + std::to_string(at.y) + ")";
      const glm::dvec3 x(at.x, at.y, 0.0);
      ++pattern;
      expectMatches("tilted emitter, Li " + where,
                    test::estimateLi(onPlane, downOnto(at.x, at.y, 0.1f), pattern, pattern, 8192),
                    kPlaneAlbedo * le * tiltedEmitterFormFactor(x, up, up));
      for (glm::dvec3 n : {up, kTiltedNormal, glm::normalize(glm::dvec3(-0.8, 0, 1))}) {
        ++pattern;
        expectMatches(
            "tilted emitter, irradiance facing (" + std::to_string(n.x) + ", 0, " +
                std::to_string(n.z) + ") " + where,
            test::estimateIrradiance(inSpace, glm::vec3(x), glm::vec3(n), pattern, pattern, 8192),
            kPiD * le * tiltedEmitterFormFactor(x, n, n));
      }
    }
  }
}

// An area emitter over a smooth-normal plane (shading normal 30° towards −x, i.e. away from
// the emitter): NEE weighs by n_s·ω, BRDF sampling draws about n_s, MIS mixes the two with
// pdfs on n_s, and the horizon is the geometric one: Lo = ρ·Le·F with the cosine on n_s and
// the polygon clipped by both planes (the shading horizon cuts the emitter as seen from the
// origin).
TEST(BlindSpots, AreaLightOnSmoothNormalsMatchesLambertsFormula) {
  const glm::dvec3 le(3, 4, 5), up(0, 0, 1);
  const glm::dvec3 away(-kTiltedNormal.x, 0.0, kTiltedNormal.z);
  test::World world = planeWorld(glm::vec3(kPlaneAlbedo), glm::vec3(away));
  addTiltedEmitter(world, le);
  world.build();
  uint32_t pattern = 700;
  for (LightStrategy strategy :
       {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BrdfOnly}) {
    TraceSettings settings;
    settings.strategy = strategy;
    const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
    for (glm::dvec2 at : {glm::dvec2(0.0, 0.0), glm::dvec2(-0.7, 0.4), glm::dvec2(1.0, 1.2)}) {
      ++pattern;
      expectMatches("area light on smooth normals, Li " + std::string(strategyName(strategy)) +
                        " at (" + std::to_string(at.x) + ", " + std::to_string(at.y) + ")",
                    test::estimateLi(tracer, downOnto(at.x, at.y, 0.1f), pattern, pattern, 8192),
                    kPlaneAlbedo * le * tiltedEmitterFormFactor({at.x, at.y, 0}, away, up));
    }
  }
}

}  // namespace
}  // namespace bounce
