// The VPL gather (vpl/vpl_gather.h) against the path tracer's indirect-only irradiance
// (PathTracer::irradiance, PathSet::IndirectOnly: light reflected at least once before it
// arrives, exactly what VPLs carry). Scene: a 4 m grey floor and a 3 m red wall standing on its
// edge x = 2 (a concave corner), a point light above. Where the VPLs are far from the receiver
// (the singularity is mild) clamped and unclamped gathers agree with the tracer; a receiver on
// the wall 3 cm above the floor sees floor VPLs at centimetres: the unclamped sum spikes from
// set to set, the clamped one stays at or below the truth and the energy it removes is
// reported. VPL estimates: the spread of K independent sets (seeds); tracer: its samples.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "trace/test_scenes.h"
#include "vpl/vpl_gather.h"
#include "vpl/vpl_generate.h"
#include "vpl_runtime/vpl_reduce.h"

namespace bounce {
namespace {

using test::addMaterial;
using test::addQuad;

test::World cornerWorld() {
  test::World world;
  addQuad(world.scene, {-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0},
          addMaterial(world.scene, glm::vec3(0.6f, 0.6f, 0.5f)));  // floor, faces +z
  addQuad(world.scene, {2, -2, 0}, {2, -2, 3}, {2, 2, 3}, {2, 2, 0},
          addMaterial(world.scene, glm::vec3(0.8f, 0.2f, 0.2f)));  // wall, faces −x
  Light light;
  light.position = {0.5f, 0.2f, 1.5f};
  light.intensity = {8, 8, 8};
  world.scene.lights.push_back(light);
  world.build();
  return world;
}

struct Spread {
  glm::dvec3 mean{0.0}, standardError{0.0}, maxValue{0.0};
  glm::dvec3 removed{0.0};  // mean energy the clamp removed
};

// K VPL sets of `paths` paths each, gathered at (x, n) with clamp distance r (0: none).
Spread gatherOverSets(const test::World& world, glm::vec3 x, glm::vec3 n, int k, int paths,
                      bool clamp) {
  std::vector<glm::dvec3> values;
  Spread s;
  const double area = surfaceArea(world.geometry);
  for (int i = 0; i < k; ++i) {
    VplSettings settings;
    settings.maxVpls = 1 << 22;
    settings.minPaths = paths;
    settings.relativeError = 1.0f;
    settings.seed = 100u + static_cast<uint32_t>(i);
    const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, settings);
    const float r = clamp ? vplClampDistance(area, set.vpls.size()) : 0.0f;
    const VplIrradiance e = gatherVplIrradiance(set.vpls, x, n, world.kernel.get(), r);
    values.push_back(e.irradiance);
    s.mean += e.irradiance / static_cast<double>(k);
    s.removed += e.removed / static_cast<double>(k);
    s.maxValue = glm::max(s.maxValue, e.irradiance);
  }
  glm::dvec3 var(0.0);
  for (const glm::dvec3& v : values) var += (v - s.mean) * (v - s.mean);
  s.standardError = glm::sqrt(var / static_cast<double>(k - 1) / static_cast<double>(k));
  return s;
}

test::Estimate tracerIndirect(const test::World& world, glm::vec3 x, glm::vec3 n) {
  TraceSettings settings;
  settings.paths = PathSet::IndirectOnly;
  const PathTracer tracer(world.scene, world.geometry, *world.kernel, settings);
  return test::estimateIrradiance(tracer, x, n, 1u, 3u, 16384);
}

TEST(VplGather, IndirectIrradianceMatchesThePathTracerWhereTheSingularityIsMild) {
  const test::World world = cornerWorld();
  const struct {
    glm::vec3 x, n;
  } receivers[] = {{{-0.5f, 0.3f, 0.0f}, {0, 0, 1}}, {{2.0f, -0.4f, 1.6f}, {-1, 0, 0}}};
  for (const auto& r : receivers) {
    const test::Estimate truth = tracerIndirect(world, r.x, r.n);
    for (bool clamp : {false, true}) {
      const Spread vpl = gatherOverSets(world, r.x, r.n, 16, 2048, clamp);
      std::printf(
          "at (%.1f, %.1f, %.1f) %s: VPL E = %.5f ± %.5f, tracer %.5f ± %.5f W/m² (red); "
          "clamp removed %.6f\n",
          r.x.x, r.x.y, r.x.z, clamp ? "clamped" : "unclamped", vpl.mean.r, vpl.standardError.r,
          truth.mean.r, truth.standardError().r, vpl.removed.r);
      EXPECT_TRUE(
          test::agreeWithin(vpl.mean, vpl.standardError, truth.mean, truth.standardError(), 5.0))
          << (clamp ? "clamped" : "unclamped");
    }
  }
}

// A receiver on the wall 3 cm above the concave corner: floor VPLs within centimetres make the
// unclamped sum spike (a set's value far above the truth); with the clamp r = sqrt(A/(πN)) the
// gather stays at or below the truth (within 5 standard errors: the bound), and the energy the
// clamp removes is reported.
TEST(VplGather, ConcaveCornerClampRemovesTheSpikes) {
  const test::World world = cornerWorld();
  const glm::vec3 x(2.0f, 0.1f, 0.03f), n(-1, 0, 0);
  const test::Estimate truth = tracerIndirect(world, x, n);
  const Spread raw = gatherOverSets(world, x, n, 16, 2048, false);
  const Spread clamped = gatherOverSets(world, x, n, 16, 2048, true);
  std::printf(
      "corner: tracer %.5f ± %.5f; unclamped mean %.5f ± %.5f, largest set %.5f; clamped "
      "%.5f ± %.5f, largest %.5f, removed %.5f W/m² (red)\n",
      truth.mean.r, truth.standardError().r, raw.mean.r, raw.standardError.r, raw.maxValue.r,
      clamped.mean.r, clamped.standardError.r, clamped.maxValue.r, clamped.removed.r);
  for (int c = 0; c < 3; ++c) {
    const double bound = 5.0 * std::sqrt(clamped.standardError[c] * clamped.standardError[c] +
                                         truth.standardError()[c] * truth.standardError()[c]);
    EXPECT_LE(clamped.mean[c], truth.mean[c] + bound) << "channel " << c;
    EXPECT_LE(clamped.maxValue[c], truth.mean[c] * 1.5) << "a clamped set spikes, channel " << c;
    EXPECT_GT(clamped.removed[c], 0.0) << "the clamp removed nothing at a corner";
  }
  EXPECT_GT(raw.maxValue.r, 1.5 * truth.mean.r) << "the unclamped sum was expected to spike";
}

}  // namespace
}  // namespace bounce

namespace bounce {
namespace {

// The two evaluators of one VPL set agree: the path tracer sampling the VPLs as lights (one
// per vertex, by power; PathSet::DirectOnly and no scene light, so only the VPLs' light after
// one reflection counts) against the exact unclamped sum of the gather, at receivers in the
// corner scene. Ties the convention the tracer checks (bake_folder/vpl.h) to the one the renderer
// will be measured against.
TEST(VplGather, PathTracerSamplingTheVplsAgreesWithTheSum) {
  test::World world = cornerWorld();
  VplSettings settings;
  settings.maxVpls = 500;
  settings.relativeError = 0.0f;
  const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, settings);
  ASSERT_GT(set.vpls.size(), 400u);
  Scene vplOnly = world.scene;
  vplOnly.lights.clear();
  TraceSettings trace;
  trace.paths = PathSet::DirectOnly;
  const PathTracer tracer(vplOnly, world.geometry, *world.kernel, trace, set.vpls);
  const struct {
    glm::vec3 x, n;
  } receivers[] = {{{-0.5f, 0.3f, 0.0f}, {0, 0, 1}}, {{2.0f, -0.4f, 1.6f}, {-1, 0, 0}}};
  for (const auto& r : receivers) {
    const VplIrradiance exact = gatherVplIrradiance(set.vpls, r.x, r.n, world.kernel.get(), 0.0f);
    const test::Estimate e = test::estimateIrradiance(tracer, r.x, r.n, 2u, 5u, 16384);
    std::printf("VPLs through the tracer: %.5f ± %.5f, sum %.5f W/m² (red)\n", e.mean.r,
                e.standardError().r, exact.irradiance.r);
    EXPECT_TRUE(
        test::agreeWithin(e.mean, e.standardError(), exact.irradiance, glm::dvec3(0.0), 5.0));
  }
}

}  // namespace
}  // namespace bounce

namespace bounce {
namespace {

// Reduction to K runtime VPLs (vpl/vpl_reduce.h): the total flux per channel is kept (to float
// rounding of the per-cluster sums), floor and wall VPLs never share a cluster (every output
// normal is exactly the floor's or the wall's), and the gather at the mild receivers, 1.5 m
// and more from the VPLs, moves by at most 5% with 64 clusters out of ~4000 (a cluster of
// radius s at distance d errs by O((s/d)²) once its centroid is flux-weighted).
TEST(VplReduce, KeepsTheTotalFluxAndTheFarField) {
  test::World world = cornerWorld();
  VplSettings settings;
  settings.maxVpls = 4000;
  settings.relativeError = 0.0f;
  const VplSet set = generateVpls(world.scene, world.geometry, *world.kernel, settings);
  const std::vector<Vpl> reduced = reduceVpls(set.vpls, 64);
  ASSERT_EQ(reduced.size(), 64u);
  glm::dvec3 before(0.0), after(0.0);
  for (const Vpl& v : set.vpls) before += glm::dvec3(v.flux);
  for (const Vpl& v : reduced) {
    after += glm::dvec3(v.flux);
    const bool floor = v.normal == glm::vec3(0, 0, 1);
    const bool wall = v.normal == glm::vec3(-1, 0, 0);
    EXPECT_TRUE(floor || wall) << "a cluster mixed normals: " << v.normal.x << " " << v.normal.y
                               << " " << v.normal.z;
  }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], before[c], 1e-6 * before[c]);
  const struct {
    glm::vec3 x, n;
  } receivers[] = {{{-0.5f, 0.3f, 0.0f}, {0, 0, 1}}, {{2.0f, -0.4f, 1.6f}, {-1, 0, 0}}};
  for (const auto& r : receivers) {
    const glm::dvec3 full =
        gatherVplIrradiance(set.vpls, r.x, r.n, world.kernel.get(), 0.0f).irradiance;
    const glm::dvec3 few =
        gatherVplIrradiance(reduced, r.x, r.n, world.kernel.get(), 0.0f).irradiance;
    std::printf("%zu VPLs: %.5f, 64 clusters: %.5f W/m² (red)\n", set.vpls.size(), full.r, few.r);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(few[c], full[c], 0.05 * full[c]) << "channel " << c;
  }
  EXPECT_EQ(reduceVpls(set.vpls, set.vpls.size()).size(), set.vpls.size());
}

}  // namespace
}  // namespace bounce
