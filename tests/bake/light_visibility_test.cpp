// The static lights' baked visibility (baker/bake/light_visibility_bake.h) against
// independent quadrature: V = ∫ E·vis / ∫ E over a light, with vis decided by an exact
// segment–rectangle test on a dense grid (not the ray kernel), and the "every other light" slot
// against Σ E_l V_l / Σ E_l with each E_l by quadrature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bake/light_visibility_bake.h"
#include "bake/texel_coverage.h"
#include "image/luminance.h"
#include "ray/ray_kernel.h"
#include "scene/area_lights.h"
#include "scene/world_geometry.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

// A rectangle corner + s·u + t·v, s, t ∈ [0, 1].
struct Rectangle {
  glm::vec3 corner, u, v;
  glm::vec3 normal() const { return glm::normalize(glm::cross(u, v)); }
};

void addRectangle(Scene& scene, const Rectangle& r, uint32_t material) {
  addQuad(scene, r.corner, r.corner + r.u, r.corner + r.u + r.v, r.corner + r.v, material);
}

// Whether the segment a→b crosses rectangle r (strictly between its ends).
bool crosses(glm::dvec3 a, glm::dvec3 b, const Rectangle& r) {
  const glm::dvec3 n = glm::cross(glm::dvec3(r.u), glm::dvec3(r.v));
  const double da = glm::dot(n, a - glm::dvec3(r.corner)),
               db = glm::dot(n, b - glm::dvec3(r.corner));
  if ((da > 0) == (db > 0) || da == db) return false;
  const glm::dvec3 x = a + (b - a) * (da / (da - db)) - glm::dvec3(r.corner);
  const double s = glm::dot(x, glm::dvec3(r.u)) / glm::dot(glm::dvec3(r.u), glm::dvec3(r.u));
  const double t = glm::dot(x, glm::dvec3(r.v)) / glm::dot(glm::dvec3(r.v), glm::dvec3(r.v));
  return s >= 0 && s <= 1 && t >= 0 && t <= 1;
}

struct Quadrature {
  double irradiance = 0.0;  // per unit radiance: ∫ cosθ_x cosθ_y / r² dA, sr
  double shadowed = 0.0;    // the same over the part no blocker hides
};

// Midpoint rule on an n × n grid over the light (front face −normal side lights x).
Quadrature integrate(const Rectangle& light, glm::vec3 x, glm::vec3 n,
                     const std::vector<Rectangle>& blockers, int grid = 400) {
  Quadrature q;
  const double dA = glm::length(glm::cross(glm::dvec3(light.u), glm::dvec3(light.v))) / grid / grid;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const glm::dvec3 y = glm::dvec3(light.corner) + (i + 0.5) / grid * glm::dvec3(light.u) +
                           (j + 0.5) / grid * glm::dvec3(light.v);
      const glm::dvec3 d = y - glm::dvec3(x);
      const double r2 = glm::dot(d, d);
      const double cosX = glm::dot(glm::dvec3(n), d),
                   cosY = -glm::dot(glm::dvec3(light.normal()), d);
      if (cosX <= 0 || cosY <= 0) continue;
      const double e = cosX * cosY / (r2 * r2) * dA;
      q.irradiance += e;
      bool hidden = false;
      for (const Rectangle& b : blockers) hidden = hidden || crosses(glm::dvec3(x), y, b);
      if (!hidden) q.shadowed += e;
    }
  return q;
}

// One covered texel with one sample point.
TexelCoverage onePoint(glm::vec3 p, glm::vec3 n) {
  TexelCoverage c;
  c.width = c.height = 1;
  c.first = {0, 1};
  c.points = {{p, n, n, {0.5f, 0.5f}, 0}};
  c.coveredArea = {1.0f};
  return c;
}

struct LitScene {
  Scene scene;
  WorldGeometry geometry;
  std::unique_ptr<RayKernel> kernel;
  AreaLightSet lights;
};

std::unique_ptr<LitScene> litScene(const std::vector<Rectangle>& lights,
                                   const std::vector<glm::vec3>& radiance,
                                   const std::vector<Rectangle>& blockers) {
  auto s = std::make_unique<LitScene>();
  const uint32_t grey = addMaterial(s->scene, glm::vec3(0.5f));
  for (std::size_t l = 0; l < lights.size(); ++l)
    addRectangle(s->scene, lights[l], addMaterial(s->scene, glm::vec3(0.0f), radiance[l]));
  for (const Rectangle& b : blockers) addRectangle(s->scene, b, grey);
  s->geometry = flatten(s->scene);
  s->kernel = makeRayKernel(s->geometry, RayBackend::Embree);
  s->lights = sceneAreaLights(s->scene);
  return s;
}

// A 1.4 m × 1.4 m light (under the 1.5 m cut, so one light) tilted 25°, 0.4 m over the point, a
// blocker hiding part of it: the form-factor weight varies ~10× over the light, so V is not the
// hidden share of its area.
TEST(LightVisibility, VisibleFractionIsTheShadowedOverTheUnshadowedIrradiance) {
  const float tilt = glm::radians(25.0f);
  // u × v faces down and towards −x (the point at the origin sees the front).
  const Rectangle light{
      {-0.5f, 0.4f, -0.7f}, {1.4f * std::cos(tilt), 1.4f * std::sin(tilt), 0}, {0, 0, 1.4f}};
  ASSERT_LT(light.normal().y, 0.0f);
  const Rectangle blocker{{-0.3f, 0.3f, -0.25f}, {0, 0, 0.5f}, {0.35f, 0, 0}};
  const auto s = litScene({light}, {glm::vec3(1.0f)}, {blocker});
  ASSERT_EQ(s->lights.staticCount(), 1u);
  const glm::vec3 x(0.0f), n(0, 1, 0);
  const Quadrature exact = integrate(light, x, n, {blocker});
  const double v = exact.shadowed / exact.irradiance;
  ASSERT_GT(v, 0.2);
  ASSERT_LT(v, 0.9);

  VisibilityBakeSettings settings;
  settings.samplesPerLight = 4096;
  VisibilityBakeReport report;
  const BakedVisibility baked =
      bakeLightVisibility(s->lights, {}, *s->kernel, onePoint(x, n), settings, report);
  ASSERT_EQ(baked.texels.size(), 1u);
  EXPECT_EQ(baked.texels[0].light[0], 0u);
  EXPECT_EQ(baked.texels[0].light[1], kNoLight);
  // A ratio of two estimates over 4096 stratified pairs: the binomial bound on one unstratified
  // fraction, √(V(1−V)/M) ≤ 0.0078, times 4.
  EXPECT_NEAR(baked.texels[0].visible[0], v, 0.03) << "exact V " << v;
  EXPECT_EQ(report.rays, 4096u);
}

// Five small lights of falling irradiance; the dimmest is hidden. The texel names the three
// brightest (V = 1) and gives its last slot to the other two: V_rest = E_3 / (E_3 + E_4).
TEST(LightVisibility, BeyondTheSlotsTheOtherLightsShareTheirIrradianceWeightedFraction) {
  std::vector<Rectangle> lights;
  std::vector<glm::vec3> radiance;
  const float xs[5] = {0.0f, 0.6f, -0.6f, 1.2f, -1.2f};
  for (int l = 0; l < 5; ++l) {
    lights.push_back({{xs[l] - 0.05f, 1.0f, -0.05f}, {0.1f, 0, 0}, {0, 0, 0.1f}});
    radiance.push_back(glm::vec3(5.0f - l));
  }
  ASSERT_LT(lights[0].normal().y, 0.0f);
  // Half-way to light 4 (at x = −1.2, y = 1): its whole image from the origin is covered.
  const Rectangle blocker{{-0.66f, 0.5f, -0.06f}, {0, 0, 0.12f}, {0.12f, 0, 0}};
  const auto s = litScene(lights, radiance, {blocker});
  ASSERT_EQ(s->lights.staticCount(), 5u);
  const glm::vec3 x(0.0f), n(0, 1, 0);
  double e[5], visible[5];
  for (int l = 0; l < 5; ++l) {
    const Quadrature q = integrate(lights[l], x, n, {blocker}, 100);
    e[l] = (5.0 - l) * q.irradiance;
    visible[l] = q.shadowed / q.irradiance;
  }
  ASSERT_NEAR(visible[4], 0.0, 1e-9);
  for (int l = 0; l < 4; ++l) ASSERT_NEAR(visible[l], 1.0, 1e-9);
  const double rest = (e[3] * visible[3] + e[4] * visible[4]) / (e[3] + e[4]);

  VisibilityBakeSettings settings;
  settings.samplesPerLight = 1024;
  VisibilityBakeReport report;
  const BakedVisibility baked =
      bakeLightVisibility(s->lights, {}, *s->kernel, onePoint(x, n), settings, report);
  const TexelVisibility& t = baked.texels[0];
  EXPECT_EQ(t.light[0], 0u);
  EXPECT_EQ(t.light[1], 1u);
  EXPECT_EQ(t.light[2], 2u);
  EXPECT_EQ(t.light[3], kOtherLights);
  for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(t.visible[k], 1.0f);
  // Lights this small are nearly points: E_3 / E_4 from 1024 area samples each is within 1%.
  EXPECT_NEAR(t.visible[3], rest, 0.01) << "exact " << rest;
  EXPECT_EQ(report.texelsOverSlots, 1u);
  EXPECT_NEAR(report.otherLightsShare, (e[3] + e[4]) / (e[0] + e[1] + e[2] + e[3] + e[4]), 0.01);
}

// A texel of nine points in a row across the shadow edges of a half-plane blocker, under a
// point, a spot and a directional light (static), a dim area light, and two lights that must
// not be named (one that moves, one whose direct light is baked). Each punctual light's V is
// Σ w_k·vis_k / Σ w_k over the points with the irradiance kernel w = I·falloff·cosθ/r² or
// E⊥·cosθ, vis decided by the exact segment–rectangle test; the map names it lightCount + its
// index in Scene::lights.
TEST(LightVisibility, PunctualLightsVisibleFractionIsTheirIrradianceWeightedShareOfTheTexel) {
  const Rectangle dim{{0.75f, 1.0f, 0.75f}, {0.1f, 0, 0}, {0, 0, 0.1f}};
  const Rectangle blocker{{-1.0f, 0.5f, -1.0f}, {0, 0, 2.0f}, {1.0f, 0, 0}};  // x < 0, y = 0.5
  auto s = litScene({dim}, {glm::vec3(1.0f)}, {blocker});
  Light point;
  point.type = LightType::Point;
  point.position = {0.1f, 1.0f, 0.0f};
  point.intensity = glm::vec3(2.0f, 1.0f, 0.5f);
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {-0.1f, 1.2f, 0.05f};
  spot.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.0f));
  spot.intensity = glm::vec3(1.5f);
  spot.innerConeAngle = 0.05f;
  spot.outerConeAngle = 0.4f;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
  sun.irradiance = glm::vec3(1.0f);
  Light moving = point, baked = point;
  moving.position.x = 0.3f;
  moving.mobility = Mobility::Dynamic;
  baked.position.x = -0.3f;
  baked.bakeDirect = true;
  const std::vector<Light> lights{point, moving, spot, baked, sun};

  TexelCoverage texel;
  texel.width = texel.height = 1;
  texel.first = {0, 9};
  texel.coveredArea = {1.0f};
  const glm::vec3 up(0, 1, 0);
  for (int k = 0; k < 9; ++k)
    texel.points.push_back({{-0.187f + 0.05f * k, 0.0f, 0.01f * k}, up, up, {0.5f, 0.5f}, 0});

  VisibilityBakeSettings settings;
  VisibilityBakeReport report;
  const BakedVisibility map =
      bakeLightVisibility(s->lights, lights, *s->kernel, texel, settings, report);
  ASSERT_EQ(map.lightCount, 1u);
  ASSERT_EQ(map.punctualCount, 5u);
  const TexelVisibility& t = map.texels[0];
  auto slotOf = [&](uint16_t light) {
    for (int k = 0; k < kVisibilitySlots; ++k)
      if (t.light[k] == light) return k;
    return -1;
  };
  EXPECT_EQ(slotOf(map.punctualIndex(1)), -1) << "the light that moves is not baked";
  EXPECT_EQ(slotOf(map.punctualIndex(3)), -1) << "the baked-direct light is not baked";
  EXPECT_EQ(t.light[3], 0u) << "the dim area light brings the least";
  for (const std::size_t l : {std::size_t{0}, std::size_t{2}, std::size_t{4}}) {
    const Light& light = lights[l];
    double sumW = 0.0, sumVisible = 0.0;
    for (const TexelPoint& x : texel.points) {
      const glm::dvec3 p(x.position);
      const bool directional = light.type == LightType::Directional;
      const glm::dvec3 to =
          directional ? p - 100.0 * glm::dvec3(light.direction) : glm::dvec3(light.position);
      const glm::dvec3 d = to - p;
      const double r = glm::length(d), cosX = d.y / r;
      double w = cosX * luminance(directional ? light.irradiance : light.intensity);
      if (!directional) w /= r * r;
      if (light.type == LightType::Spot) {
        const double cosTheta = glm::dot(-d / r, glm::dvec3(light.direction));
        const double f =
            std::clamp((cosTheta - std::cos(0.4)) / (std::cos(0.05) - std::cos(0.4)), 0.0, 1.0);
        w *= f * f;
      }
      sumW += w;
      if (!crosses(p, to, blocker)) sumVisible += w;
    }
    const double v = sumVisible / sumW;
    const int slot = slotOf(map.punctualIndex(l));
    ASSERT_GE(slot, 0) << "light " << l << " is named";
    EXPECT_NEAR(t.visible[slot], v, 1e-5) << "light " << l;
    EXPECT_GT(v, 0.05) << "light " << l << ": the row crosses its shadow edge";
    EXPECT_LT(v, 0.95) << "light " << l << ": the row crosses its shadow edge";
  }
  EXPECT_EQ(report.punctualLights, 5u);
}

// Texels without points take a neighbour's record, their chart's first.
TEST(LightVisibility, UncoveredTexelsTakeANeighboursRecord) {
  BakedVisibility v;
  v.width = 4;
  v.height = 1;
  v.lightCount = 2;
  v.texels.resize(4);
  v.texels[1].light = {0, kNoLight, kNoLight, kNoLight};
  v.texels[1].visible = {0.25f, 1, 1, 1};
  v.texels[3].light = {1, kNoLight, kNoLight, kNoLight};
  v.texels[3].visible = {0.75f, 1, 1, 1};
  const std::vector<uint32_t> labels{1, 1, 2, 2};
  fillVisibility(v, {0, 1, 0, 1}, &labels);
  EXPECT_EQ(v.texels[0].light[0], 0u);
  EXPECT_FLOAT_EQ(v.texels[0].visible[0], 0.25f);
  EXPECT_EQ(v.texels[2].light[0], 1u);  // its chart's neighbour, not the nearer-in-order one
  EXPECT_FLOAT_EQ(v.texels[2].visible[0], 0.75f);
}

// A chart none of whose texels kept points (a strip of floor or wall inside a thin wall, drawn
// only where two faces meet at a multisampled edge pixel) is dark to every light, not lit by
// the chart across the wall; the padding between charts still takes a chart's record. Injected:
// the unfilled chart left to the cross-chart fill: it takes chart 1's V = 1 (the thin-wall edge
// pixel of ThinWallLeak.NoLightmapLightAtTheDarkRoomsMultisampledEdgePixels leaks then when the
// spot and point maps are drawn for dynamic instances alone).
TEST(LightVisibility, AChartWithoutPointsIsDarkToEveryLight) {
  BakedVisibility v;
  v.width = 5;
  v.height = 1;
  v.lightCount = 1;
  v.punctualCount = 1;
  v.texels.resize(5);
  v.texels[0].light = {0, 1, kNoLight, kNoLight};  // lit by both lights
  v.texels[0].visible = {1, 1, 1, 1};
  const std::vector<uint32_t> labels{1, 0, 0, 2, 2};  // chart 1, padding, chart 2
  fillVisibility(v, {1, 0, 0, 0, 0}, &labels);
  for (const std::size_t t : {3u, 4u}) {
    EXPECT_EQ(v.texels[t].light[0], kOtherLights) << "texel " << t;
    EXPECT_FLOAT_EQ(v.texels[t].visible[0], 0.0f) << "texel " << t;
    for (int s = 1; s < kVisibilitySlots; ++s) EXPECT_EQ(v.texels[t].light[s], kNoLight);
  }
  EXPECT_EQ(v.texels[1].light[0], 0u);            // padding next to chart 1: its record
  EXPECT_EQ(v.texels[2].light[0], kOtherLights);  // padding next to chart 2: the dark one
}

}  // namespace
}  // namespace bounce::test
