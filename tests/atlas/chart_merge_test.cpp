// Merging of narrow and medium charts (chart_merge.h) and joining along one run of a shared
// boundary (chart_join.h), on shapes built here at 5 cm texels: a thin tube, a pleated curtain and
// a thin double-sided plank each end as one chart, laid out with no overlap, the padding kept and
// every triangle's texel density within [1/2, 2] of the scene's; a 40 cm box keeps its six faces.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <glm/gtc/matrix_transform.hpp>

#include "atlas/atlas.h"
#include "atlas_scenes.h"
#include "layout_checks.h"

namespace bounce::test {
namespace {

constexpr float kTexel = 0.05f;  // m

uint32_t addMesh(Scene& scene, Mesh mesh) {
  if (scene.materials.empty()) scene.materials.push_back(Material{});
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
  scene.meshes.push_back(std::move(mesh));
  return static_cast<uint32_t>(scene.meshes.size() - 1);
}

// A zig-zag sheet 1 m tall of `facets` vertical facets `width` m wide, each turned ±25° from the
// x axis, so neighbouring facets meet at a 50° fold (sharper than the segmentation's 35° crease).
uint32_t addPleatedMesh(Scene& scene, int facets, float width) {
  Mesh mesh;
  mesh.name = "pleats";
  const float angle = 25.0f * 3.14159265f / 180.0f;
  glm::vec3 at(0.0f);
  for (int f = 0; f <= facets; ++f) {
    mesh.positions.push_back(at);
    mesh.positions.push_back(at + glm::vec3(0, 1, 0));
    const float z = (f % 2 == 0 ? 1.0f : -1.0f) * std::sin(angle) * width;
    at += glm::vec3(std::cos(angle) * width, 0, z);
  }
  for (uint32_t f = 0; f < static_cast<uint32_t>(facets); ++f) {
    const uint32_t a = 2 * f, b = a + 1, c = a + 2, d = a + 3;
    mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
  }
  return addMesh(scene, std::move(mesh));
}

// A plank of no thickness, `length` × `width` m in z = 0: its front (+z) and back (−z) share the
// four rim edges and nothing else (the front split along one diagonal, the back along the other),
// a closed surface that no single map lays flat.
uint32_t addDoubleSidedPlankMesh(Scene& scene, float length, float width) {
  Mesh mesh;
  mesh.name = "plank";
  mesh.positions = {{0, 0, 0}, {length, 0, 0}, {length, width, 0}, {0, width, 0}};
  mesh.indices = {0, 1, 2, 0, 2, 3,   // front, diagonal 0-2
                  0, 3, 1, 1, 3, 2};  // back, diagonal 1-3
  return addMesh(scene, std::move(mesh));
}

struct InstanceCharts {
  std::size_t charts = 0;
  double lowestDensity = INFINITY, highestDensity = 0.0;  // texel area / (world area / t²)
};

InstanceCharts chartsOf(const Scene& scene, const Atlas& atlas, uint32_t instance) {
  InstanceCharts result;
  const InstanceLightmapUv* region = atlas.layout.find(instance);
  if (region == nullptr) return result;
  const std::size_t slot = static_cast<std::size_t>(region - atlas.layout.instances.data());
  const std::set<uint32_t> charts(atlas.triangleChart[slot].begin(),
                                  atlas.triangleChart[slot].end());
  result.charts = charts.size();
  const Instance& placed = scene.instances[instance];
  const Mesh& mesh = scene.meshes[placed.mesh];
  const glm::vec2 size(static_cast<float>(atlas.layout.width),
                       static_cast<float>(atlas.layout.height));
  const double t = atlas.layout.texelSize;
  for (std::size_t tri = 0; tri < mesh.triangleCount(); ++tri) {
    glm::dvec3 p[3];
    glm::dvec2 uv[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = glm::dvec3(placed.transform * glm::vec4(mesh.positions[mesh.indices[3 * tri + k]], 1));
      uv[k] = glm::dvec2(region->cornerUv[3 * tri + k] * size);
    }
    const double world = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) / (t * t);
    const glm::dvec2 e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
    const double texels = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
    result.lowestDensity = std::min(result.lowestDensity, texels / world);
    result.highestDensity = std::max(result.highestDensity, texels / world);
  }
  return result;
}

}  // namespace

TEST(AtlasMerge, TubesPleatsAndPlanksBecomeOneChartBoxesKeepTheirFaces) {
  Scene scene;
  // A tube of radius 2 cm and length 4 m, 8 facets around: the segmentation's 43° cone cuts it
  // into strips 0.6 texel wide (each 3 × 82 texels with its padding); one chart 2.5 texels wide.
  addInstance(scene, addCylinderMesh(scene, 8),
              glm::scale(glm::mat4(1.0f), glm::vec3(0.02f, 2.0f, 0.02f)));
  // A curtain of 12 pleats 10 cm wide (2 × 20 texels each, medium charts) folded by 50°.
  addInstance(scene, addPleatedMesh(scene, 12, 0.1f),
              glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1)));
  // A 30 × 3 cm double-sided plank: front and back tiny charts sharing their whole rim.
  addInstance(scene, addDoubleSidedPlankMesh(scene, 0.3f, 0.03f),
              glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 2)));
  // A 40 cm box: faces of 8 × 8 texels (medium) meet at 90°, never merged.
  addInstance(scene, addUnitCubeMesh(scene),
              glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 3)) *
                  glm::scale(glm::mat4(1.0f), glm::vec3(0.4f)));
  AtlasSettings settings;
  settings.texelSize = kTexel;
  // The merges are under test: keep a lightmap for the plank and the tube, which fill under
  // kMinLightmapFill of their padded texels (the VPLs would light them by default).
  settings.minLightmapFill = 0.0;
  const Atlas atlas = buildAtlas(scene, settings);
  EXPECT_EQ(regionProblem(scene, atlas), "");
  EXPECT_EQ(overlapProblem(atlas), "");
  const char* names[] = {"tube", "pleats", "plank", "box"};
  const std::size_t expected[] = {1, 1, 1, 6};
  for (uint32_t i = 0; i < 4; ++i) {
    const InstanceCharts charts = chartsOf(scene, atlas, i);
    std::printf("%s: %zu charts, texel density per triangle in [%.3f, %.3f] of the scene's\n",
                names[i], charts.charts, charts.lowestDensity, charts.highestDensity);
    EXPECT_EQ(charts.charts, expected[i]) << names[i];
    EXPECT_GE(charts.lowestDensity, 0.5) << names[i];
    EXPECT_LE(charts.highestDensity, 2.0) << names[i];
  }
}

// The merge pass is serial by definition (smallest chart first, each choice made on the charts as
// the earlier merges left them); it runs as windows of choices made in parallel and carried out in
// order (chart_merge.cpp). One instance whose small charts merge into one another in chains, so
// that choices in one window go stale: 200 pleats 1 cm wide folded by 50° (each narrow, each
// joining its neighbour) and a sphere of radius 15 cm in 16 × 32 facets at 5 cm texels (tiny
// charts). In a one-thread arena the window is one chart, the serial pass itself; in an
// eight-thread arena eight: the same charts, bit for bit.
TEST(AtlasMerge, WindowsOfParallelChoicesGiveTheSerialPassesCharts) {
  Scene scene;
  const uint32_t pleats = addPleatedMesh(scene, 200, 0.01f);
  const uint32_t sphere = addSphereMesh(scene, 16, 32);
  Mesh both = scene.meshes[pleats];
  const Mesh& ball = scene.meshes[sphere];
  const auto first = static_cast<uint32_t>(both.positions.size());
  for (const glm::vec3& p : ball.positions)
    both.positions.push_back(p * 0.15f + glm::vec3(0, 2, 0));
  for (const uint32_t v : ball.indices) both.indices.push_back(first + v);
  scene.meshes.clear();
  addInstance(scene, addMesh(scene, std::move(both)), glm::mat4(1.0f));
  AtlasSettings settings;
  settings.texelSize = kTexel;
  settings.minLightmapFill = 0.0;  // keep the lightmap whatever its fill
  // Eight threads allowed whatever the machine's cores, so the window is eight in that arena.
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 8);
  const auto layOut = [&](int threads) {
    Atlas atlas;
    tbb::task_arena(threads).execute([&] { atlas = buildAtlas(scene, settings); });
    return atlas;
  };
  const Atlas serial = layOut(1), windowed = layOut(8);
  EXPECT_EQ(regionProblem(scene, serial), "");
  std::printf("%d charts\n", serial.layout.chartCount);
  ASSERT_EQ(serial.layout.instances.size(), 1u);
  ASSERT_EQ(windowed.layout.instances.size(), 1u);
  EXPECT_EQ(serial.layout.chartCount, windowed.layout.chartCount);
  EXPECT_TRUE(serial.triangleChart[0] == windowed.triangleChart[0]);
  EXPECT_TRUE(serial.layout.instances[0].cornerUv == windowed.layout.instances[0].cornerUv);
}

}  // namespace bounce::test
