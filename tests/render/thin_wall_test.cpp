// No lightmap light through a wall thinner than a texel (issue 15, docs/real_scenes.md "Light
// through thin walls"): where a wall crosses a floor, a ceiling or a side wall, the surface is cut
// (scene/crossing_cuts.h) so that no chart runs under the wall, and the renderer's bilinear
// lookup on the dark side reads only the dark side's texels. And no needless cuts: a quad that
// nothing crosses stays one chart, a table leg standing on a floor does not cut it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "atlas/atlas.h"
#include "bake/lightmap_filters.h"
#include "image/luminance.h"
#include "indirect_accuracy.h"
#include "thin_wall_scene.h"

namespace bounce {
namespace {

// The lightmap's bilinear lookup (the renderer's filter) at world point p on instance i's surface
// (the triangle holding p, within 1 mm of its plane), or nothing where no triangle holds it.
std::optional<glm::vec3> lookup(const Scene& scene, const Bake& bake, uint32_t i, glm::vec3 p) {
  const InstanceLightmapUv* region = bake.layout.find(i);
  if (region == nullptr) return std::nullopt;
  const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
  const glm::mat4& m = scene.instances[i].transform;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    glm::vec3 c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[3 * t + k]], 1));
    const glm::vec3 n = glm::cross(c[1] - c[0], c[2] - c[0]);
    const float area2 = glm::length(n);
    if (!(area2 > 0.0f) || std::abs(glm::dot(n / area2, p - c[0])) > 1e-3f) continue;
    float b[3];
    for (int k = 0; k < 3; ++k)
      b[k] = glm::dot(glm::cross(c[(k + 2) % 3] - c[(k + 1) % 3], p - c[(k + 1) % 3]), n) /
             (area2 * area2);
    if (std::min({b[0], b[1], b[2]}) < -1e-5f) continue;
    glm::vec2 uv(0.0f);
    for (int k = 0; k < 3; ++k) uv += b[k] * region->cornerUv[3 * t + k];
    const glm::vec2 size(static_cast<float>(bake.layout.width),
                         static_cast<float>(bake.layout.height));
    return bilinear(bake.irradiance, uv * size);
  }
  return std::nullopt;
}

// Points on the surfaces the wall crosses, at distance `d` from the wall's face on side `s`
// (+1 the dark room, −1 the lit one): (instance, point) pairs along the floor, the ceiling and
// both side walls.
std::vector<std::pair<uint32_t, glm::vec3>> nearTheWall(float t, float d, float s) {
  std::vector<std::pair<uint32_t, glm::vec3>> points;
  const float x = s * (t / 2 + d);
  for (float w = -0.95f; w <= 0.95f; w += 0.0375f) {
    points.push_back({0, {x, 0.0f, w}});           // floor
    points.push_back({1, {x, 2.5f, w}});           // ceiling
    points.push_back({2, {x, 1.25f + w, -1.0f}});  // side wall z = −1
    points.push_back({3, {x, 1.25f + w, 1.0f}});   // side wall z = +1
  }
  return points;
}

// The dark room's lookups near a 2 cm wall (a fifth of a 10 cm texel), at every distance from
// its face down to 0.5 mm, against 1 % of the lit room's mean at the mirrored points. The path
// tracer's answer there is exactly 0: no light reaches the dark room (every path to it crosses
// the wall), so a cut lightmap holds exactly 0 in every dark texel and the bound has no noise to
// allow for; the 1 % is the goal. Without the cut (scene as written) the floor's texels
// straddle the wall: measured 40 % of the lit mean (docs/real_scenes.md).
TEST(ThinWallLeak, NoLightmapLightInTheBilinearLookupBeyondAWallThinnerThanATexel) {
  const float t = 0.02f;
  const Scene scene = test::thinWallRooms(t);
  SceneBakeSettings settings = test::lightmapOnlySettings();
  settings.texelSize = 0.1f;
  settings.maxSpp = 64;
  const Bake bake = bakeScene(scene, settings).folder;
  double litSum = 0.0;
  int lit = 0;
  for (const float d : {0.0005f, 0.01f, 0.03f, 0.06f, 0.1f, 0.2f, 0.4f})
    for (const auto& [i, p] : nearTheWall(t, d, -1.0f))
      if (const auto e = lookup(scene, bake, i, p)) litSum += luminance(*e), ++lit;
  ASSERT_GT(lit, 600);
  const double litMean = litSum / lit;  // W/m²
  ASSERT_GT(litMean, 0.0);
  int dark = 0;
  for (const float d : {0.0005f, 0.01f, 0.03f, 0.06f, 0.1f, 0.2f, 0.4f})
    for (const auto& [i, p] : nearTheWall(t, d, 1.0f)) {
      const auto e = lookup(scene, bake, i, p);
      ASSERT_TRUE(e.has_value()) << "instance " << i << " at " << p.x << "," << p.y << "," << p.z;
      EXPECT_LE(luminance(*e), 0.01 * litMean) << "instance " << i << " at " << p.x << "," << p.y
                                               << "," << p.z << " (" << d << " m from the wall)";
      ++dark;
    }
  EXPECT_EQ(dark, lit);
}

// The same rooms drawn by the renderer with 4 samples a pixel, from a camera in the dark room
// facing the wall, at frames whose pixels span a texel or more: every pixel of the dark room's
// full frame under 1% of the lit room's mean (the path tracer's answer is exactly 0). At the
// corners where the floor and ceiling meet the side walls a pixel is partly covered by two
// triangles; each is shaded at a point its samples choose, and its lightmap lookup must stay on
// its own chart. Measured before the lookups were clamped into their triangle (forward.geom):
// 32% at 24 pixels, 36% at 16, 8.9% at 32 (llvmpipe).
TEST(ThinWallLeak, NoLightmapLightAtTheDarkRoomsMultisampledEdgePixels) {
  const Scene scene = test::thinWallRooms(0.02f);
  SceneBakeSettings settings = test::lightmapOnlySettings();
  settings.texelSize = 0.1f;
  settings.maxSpp = 64;
  const Bake bake = bakeScene(scene, settings).folder;
  test::testContext();
  RendererSettings full;
  full.mode = RenderMode::Full;
  ForwardRenderer renderer(scene, gl::shaderDirectory(), full, &bake);
  const Camera dark = test::lookingAt({1.9f, 1.2f, 0.0f}, {0.0f, 0.8f, 0.0f}, 1.4f);
  const Camera lit = test::lookingAt({-1.9f, 1.2f, 0.0f}, {0.0f, 0.8f, 0.0f}, 1.4f);
  for (const int size : {16, 24, 32}) {
    double litMean = 0.0;
    const Image litFrame = renderer.renderImage(lit, size, size, 4);
    for (const glm::vec3& p : litFrame.pixels) litMean += luminance(p);
    litMean /= static_cast<double>(litFrame.pixels.size());
    ASSERT_GT(litMean, 0.0);
    const Image darkFrame = renderer.renderImage(dark, size, size, 4);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        EXPECT_LE(luminance(darkFrame.at(x, y)), 0.01 * litMean)
            << "pixel " << x << "," << y << " of the " << size << "-pixel frame";
  }
}

// Charts never hold triangles on both sides of the wall: each chart's triangles lie on one side
// (centroids x < −t/2, inside [−t/2, t/2], or x > t/2) on the floor, ceiling and side walls.
TEST(AtlasCrossingCuts, NoChartOfTheCrossedSurfacesHoldsBothSidesOfTheWall) {
  const float t = 0.005f;
  const Scene scene = test::thinWallRooms(t);
  AtlasSettings settings;
  settings.texelSize = 0.1f;
  const Atlas atlas = buildAtlas(scene, settings);
  for (std::size_t r = 0; r < atlas.layout.instances.size(); ++r) {
    const uint32_t i = atlas.layout.instances[r].instance;
    if (i > 3) continue;  // the floor, the ceiling, the two side walls
    const Mesh& mesh = scene.meshes[scene.instances[i].mesh];
    EXPECT_GT(mesh.triangleCount(), 2u) << "instance " << i << " was not cut";
    std::vector<int> side(static_cast<std::size_t>(atlas.layout.chartCount), 2);  // 2: none yet
    for (std::size_t tri = 0; tri < mesh.triangleCount(); ++tri) {
      glm::vec3 c(0.0f);
      for (int k = 0; k < 3; ++k) c += mesh.positions[mesh.indices[3 * tri + k]] / 3.0f;
      const int s = c.x < -t / 2 ? -1 : c.x > t / 2 ? 1 : 0;
      int& chart = side[atlas.triangleChart[r][tri]];
      if (chart == 2) chart = s;
      EXPECT_EQ(chart, s) << "instance " << i << " triangle " << tri;
    }
  }
}

// A floor quad crossed by nothing stays two triangles and one chart; a table leg (a 5 cm box)
// standing on it does not cut it (its foot covers under kCoverage of any chord of the floor).
TEST(AtlasCrossingCuts, NoCutWhereNothingCrossesOrALegStands) {
  Scene scene;
  test::addQuad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, test::matteMaterial("floor", 0.5f));
  Scene alone = scene;
  EXPECT_EQ(cutAtCrossings(alone).cutTriangles, 0u);
  EXPECT_TRUE(alone.meshes[0].cutEdges.empty());
  test::addBox(scene, {0.2f, 0, 0.2f}, {0.25f, 0.7f, 0.25f}, test::matteMaterial("leg", 0.5f));
  const CrossingCuts cuts = cutAtCrossings(scene);
  EXPECT_EQ(cuts.cutTriangles, 0u);
  EXPECT_EQ(scene.meshes[0].triangleCount(), 2u);
  AtlasSettings settings;
  settings.texelSize = 0.05f;
  const Atlas atlas = buildAtlas(scene, settings);
  ASSERT_EQ(atlas.layout.instances.size(), 2u);
  EXPECT_EQ(atlas.triangleChart[0][0], atlas.triangleChart[0][1]) << "the floor is one chart";
}

// Cutting twice changes nothing more: the pieces of the first cut lie on one side of each plane.
TEST(AtlasCrossingCuts, CuttingTwiceAddsNothing) {
  Scene scene = test::thinWallRooms(0.02f);
  std::size_t triangles = scene.triangleCount();
  EXPECT_EQ(cutAtCrossings(scene).cutTriangles, 0u);
  EXPECT_EQ(scene.triangleCount(), triangles);
}

}  // namespace
}  // namespace bounce
