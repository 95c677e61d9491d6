// GL-free: the static area lights' irradiance vectors per triangle corner of a probe-lit instance
// (render/static_direct_corners.h), under an off-centre panel of unequal RGB radiance, every
// corner's visibility V = 0.4 for it. A small triangle (edge 0.1 m, 0.5 m from the panel) with
// a different tilted normal at each corner is read from its corners: each holds V·F_c with n·F_c
// the exact irradiance (Lambert's formula written apart, support/polygon_form_factor.h) at that
// corner's vertex and normal. A triangle of 1 m edges as near is left per pixel: w = 0, F = 0.
#include "render/static_direct_corners.h"

#include <gtest/gtest.h>

#include <numbers>

#include "support/polygon_form_factor.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

constexpr float kV = 0.4f;

glm::vec3 exactIrradiance(const Scene& scene, glm::vec3 p, glm::vec3 n) {
  std::vector<glm::dvec3> polygon;
  for (const glm::vec3& v : scene.meshes[0].positions) polygon.emplace_back(v);
  const std::vector<glm::dvec3> clipped = clipPolygon(polygon, glm::dvec3(p), glm::dvec3(n));
  if (clipped.size() < 3) return glm::vec3(0.0f);
  const double f = std::abs(polygonFormFactor(clipped, glm::dvec3(p), glm::dvec3(n)));
  return scene.materials[0].emission * static_cast<float>(std::numbers::pi * f);
}

TEST(StaticDirectCorners, SmallTrianglesHoldVTimesEachCornersExactVectorLargeOnesAreLeftPerPixel) {
  Scene scene;
  Material panel;
  panel.name = "panel";
  panel.emission = glm::vec3(3.0f, 2.0f, 1.0f);
  addQuad(scene, {0.1f, 0.5f, -0.4f}, {0.3f, 0, 0}, {0, 0, 0.2f}, panel);  // faces −y
  Mesh object;
  object.name = "object";
  object.material = 1;
  Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.5f);
  scene.materials.push_back(grey);
  // Triangle 0: small, under the panel; triangle 1: 1 m edges at the same height.
  object.positions = {{0.15f, 0.0f, -0.3f}, {0.25f, 0.0f, -0.3f}, {0.2f, 0.02f, -0.22f},
                      {-0.6f, 0.0f, 0.3f},  {0.4f, 0.0f, 0.3f},   {-0.1f, 0.0f, -0.5f}};
  object.normals = {glm::normalize(glm::vec3(0.3f, 1, 0)),
                    glm::normalize(glm::vec3(-0.2f, 1, 0.4f)),
                    glm::normalize(glm::vec3(0, 1, -0.5f)),
                    {0, 1, 0},
                    {0, 1, 0},
                    {0, 1, 0}};
  object.indices = {0, 1, 2, 3, 4, 5};
  scene.meshes.push_back(object);
  Instance instance;
  instance.name = "object";
  instance.mesh = 1;
  scene.instances.push_back(instance);

  IrradianceProbes probes;
  ProbeGrid grid;
  grid.instance = 1;
  grid.firstCorner = 0;
  grid.cornerCount = 6;
  probes.grids = {grid};
  probes.visibility.lightCount = 1;
  TexelVisibility record;
  record.light[0] = 0;
  record.visible[0] = kV;
  probes.visibility.corners.assign(6, record);
  const AreaLightSet lights = sceneAreaLights(scene);
  ASSERT_EQ(lights.lights.size(), 1u);

  const std::vector<glm::vec4> f =
      staticDirectCorners(scene, probes, PrecomputedLights{&lights, 1, {}, {}});
  ASSERT_EQ(f.size(), 18u);
  for (std::size_t k = 0; k < 3; ++k) {
    const glm::vec3 n = object.normals[k];
    const glm::vec3 expected = kV * exactIrradiance(scene, object.positions[k], n);
    ASSERT_GT(expected.b, 0.0f);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(f[3 * k + c].w, 1.0f) << "corner " << k;
      EXPECT_NEAR(glm::dot(n, glm::vec3(f[3 * k + c])), expected[c], 1e-4f * expected[c])
          << "corner " << k << " channel " << c;
    }
  }
  for (std::size_t k = 3; k < 6; ++k)
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(f[3 * k + c], glm::vec4(0.0f)) << "corner " << k << " of the large triangle";
}

}  // namespace
}  // namespace bounce::test
