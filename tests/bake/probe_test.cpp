// Irradiance probes (bake/irradiance_probes.h) against closed forms: the L1 projection of a known
// radiance field, and probes in a closed furnace.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "bake/irradiance_cache.h"
#include "bake/irradiance_probes.h"
#include "bake/lightmap_bake.h"
#include "bake_folder/lightmap_layout.h"
#include "bake_folder/probe_file.h"
#include "test_scenes.h"
#include "trace/indirect_cache.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

// 26 normals: the axes, the face diagonals and the cube's corners.
std::vector<glm::vec3> testNormals() {
  std::vector<glm::vec3> normals;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) normals.push_back(glm::normalize(glm::vec3(x, y, z)));
  return normals;
}

// Incoming radiance L(ω) = a + b·ω + c·(3ω_z² − 1) (W/(sr·m²)): bands 0, 1 and 2. Its irradiance
// is E(n) = Â0·a + Â1·b·n + Â2·c·(3n_z² − 1) with the clamped cosine's Â0 = π, Â1 = 2π/3,
// Â2 = π/4 (Ramamoorthi & Hanrahan 2001); the L1 projection of E keeps the first two terms only.
TEST(ProbeProjection, L1OfAKnownRadianceFieldKeepsItsFirstTwoBandsConvolved) {
  const double a = 1.0, c = 0.4;
  const glm::dvec3 b(0.3, -0.2, 0.5);
  const auto irradiance = [&](glm::dvec3 n) {
    return kPi * a + 2.0 * kPi / 3.0 * glm::dot(b, n) + kPi / 4.0 * c * (3.0 * n.z * n.z - 1.0);
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  ShProjection projection;
  constexpr int kSamples = 1 << 16;
  // The sample deviation of each coefficient's integrand 4π·Y·E, for the tolerance.
  double m2[4] = {0, 0, 0, 0}, mean[4] = {0, 0, 0, 0};
  for (int i = 0; i < kSamples; ++i) {
    const float z = 1.0f - 2.0f * u(rng), phi = 2.0f * kPi * u(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const glm::vec3 n(r * std::cos(phi), r * std::sin(phi), z);
    const double e = irradiance(glm::dvec3(n));
    projection.add(n, glm::vec3(static_cast<float>(e)));
    const std::array<float, 4> y = shBasisL1(n);
    for (int k = 0; k < 4; ++k) {
      const double x = 4.0 * kPi * y[k] * e, d = x - mean[k];
      mean[k] += d / (i + 1);
      m2[k] += d * (x - mean[k]);
    }
  }
  double sd[4];
  for (int k = 0; k < 4; ++k) sd[k] = std::sqrt(m2[k] / (kSamples - 1) / kSamples);
  const ProbeIrradiance p = projection.mean();
  for (const glm::vec3& n : testNormals()) {
    const double exact = kPi * a + 2.0 * kPi / 3.0 * glm::dot(b, glm::dvec3(n));
    // The reconstruction's standard error: Σ |Y_k(n)|·σ_k bounds it.
    const std::array<float, 4> y = shBasisL1(n);
    double tolerance = 0.0;
    for (int k = 0; k < 4; ++k) tolerance += 5.0 * std::abs(y[k]) * sd[k];
    EXPECT_NEAR(probeIrradianceAt(p, n).r, exact, tolerance)
        << "n = (" << n.x << ", " << n.y << ", " << n.z << ")";
  }
  // A uniform field gives E(n) = π·L for every n: E00 = π·L/Y00.
  EXPECT_NEAR(p.sh[0].r * kShY00, kPi * a, 5.0 * kShY00 * sd[0]);
}

// Appends a closed cube facing outwards to `mesh`: six quads (addInwardBox's, wound the other
// way).
void appendOutwardCube(Mesh& mesh, glm::vec3 lo, glm::vec3 hi) {
  Scene faces;
  test::addInwardBox(faces, lo, hi, 0);
  for (const Mesh& face : faces.meshes) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (std::size_t v = 0; v < face.positions.size(); ++v) {
      mesh.positions.push_back(face.positions[v]);
      mesh.normals.push_back(-face.normals[v]);
    }
    for (uint32_t k : {0u, 2u, 1u, 0u, 3u, 2u}) mesh.indices.push_back(base + k);
  }
}

// A closed cube facing outwards as one instance.
uint32_t addOutwardCube(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
  Mesh mesh;
  mesh.name = "cube";
  mesh.material = material;
  appendOutwardCube(mesh, lo, hi);
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  instance.name = "cube";
  scene.instances.push_back(instance);
  return static_cast<uint32_t>(scene.instances.size() - 1);
}

struct FurnaceWithCube {
  test::World world;
  uint32_t cube = 0;
  FurnaceWithCube(float rho, float le) {
    const uint32_t m = test::addMaterial(world.scene, glm::vec3(rho), glm::vec3(le));
    test::addInwardBox(world.scene, glm::vec3(0.0f), glm::vec3(1.0f), m);
    // On the floor: the grid's lowest layer lies under the floor, outside the furnace.
    cube = addOutwardCube(world.scene, {0.4f, 0.4f, 0.0f}, {0.6f, 0.6f, 0.16f}, m);
    world.build();
  }
};

// Closed box of albedo ρ whose every surface (walls and the cube inside) emits Le: the radiance is
// L = Le/(1 − ρ) everywhere, so the light that reflected at least once gives every normal the
// irradiance E = π·Le·ρ/(1 − ρ) (tests/bake/physics_test.cpp). Every probe's reconstruction must
// hold it for every normal within 5 of its estimated standard errors; the probes under the floor
// (outside the furnace, seeing the back of the floor) and inside the cube must be found and
// filled from the others.
TEST(IrradianceProbes, FurnaceReconstructsTheExactIrradianceForEveryNormal) {
  const float rho = 0.5f, le = 1.0f;
  const FurnaceWithCube furnace(rho, le);
  ProbeSettings settings;
  settings.maxSpp = 2048;
  settings.targetError = 0.03f;
  settings.seed = 5;
  const std::vector<ProbedInstance> instances = {{furnace.cube, furnace.cube}};
  const ProbeBake bake = bakeIrradianceProbes(furnace.world.scene, furnace.world.geometry,
                                              *furnace.world.kernel, instances, settings);
  ASSERT_EQ(bake.probes.grids.size(), 1u);
  const ProbeGrid& grid = bake.probes.grids[0];
  EXPECT_EQ(grid.instance, furnace.cube);
  const double exact = kPi * le * rho / (1.0 - rho);
  float worst = 0.0f;
  for (std::size_t i = 0; i < bake.relativeError.size(); ++i)
    if (!bake.invalid[i]) worst = std::max(worst, bake.relativeError[i]);
  ASSERT_GT(worst, 0.0f);
  uint32_t index = 0, invalid = 0, underFloorCount = 0;
  for (uint32_t z = 0; z < grid.counts.z; ++z)
    for (uint32_t y = 0; y < grid.counts.y; ++y)
      for (uint32_t x = 0; x < grid.counts.x; ++x, ++index) {
        const glm::vec3 p = grid.position({x, y, z});
        const bool underFloor = p.z < 0.0f;
        const bool inCube = glm::all(glm::greaterThan(p, glm::vec3(0.4f, 0.4f, 0.0f))) &&
                            glm::all(glm::lessThan(p, glm::vec3(0.6f, 0.6f, 0.16f)));
        EXPECT_EQ(bake.invalid[index] != 0, underFloor || inCube) << "probe " << index;
        underFloorCount += underFloor ? 1 : 0;
        invalid += bake.invalid[index];
        // A filled probe is a weighted mean of valid ones: within the worst one's error.
        const double error = bake.invalid[index] ? worst : bake.relativeError[index];
        for (const glm::vec3& n : testNormals())
          EXPECT_NEAR(luminance(probeIrradianceAt(bake.probes.probes[index], n)), exact,
                      5.0 * error * exact + 1e-9)
              << "probe " << index << " n = (" << n.x << ", " << n.y << ", " << n.z << ")";
      }
  EXPECT_EQ(underFloorCount, grid.counts.x * grid.counts.y);
  EXPECT_GT(invalid, underFloorCount);  // and some inside the cube
  EXPECT_EQ(bake.unfilled, 0u);
  for (const uint8_t n : bake.needed) EXPECT_EQ(n, 1);  // the cube's boxes reach every cell
  EXPECT_EQ(bake.nonFiniteSamples, 0u);
}

// The furnace's light that reflected at least once is π·Le·ρ/(1 − ρ) W/m² at every surface point:
// a cache holding it exactly (what a converged lightmap of the furnace holds).
class ExactFurnaceCache final : public IndirectCache {
 public:
  explicit ExactFurnaceCache(double e) : e_(static_cast<float>(e)) {}
  std::optional<glm::vec3> irradianceAt(const SurfacePoint&, glm::vec3) const override {
    return glm::vec3(e_);
  }

 private:
  float e_;
};

// Probes whose paths end at a cache after one reflection (ProbeSettings::cache, the delivered
// lightmap in a bake) estimate the same light: in the furnace, with the cache exact, every probe
// still holds π·Le·ρ/(1 − ρ) for every normal within 5 of its standard errors, and what is left
// to sample is the next-event estimate at the first hit: at the same samples the probes are
// closer to it than whole paths' (a cache never read gives the same probes).
TEST(IrradianceProbes, PathsEndingAtAnExactCacheHoldTheFurnacesLightMoreClosely) {
  const float rho = 0.5f, le = 1.0f;
  const FurnaceWithCube furnace(rho, le);
  const double exact = kPi * le * rho / (1.0 - rho);
  const ExactFurnaceCache cache(exact);
  ProbeSettings settings;
  settings.maxSpp = 2048;
  settings.targetError = 0.03f;
  settings.seed = 5;
  const std::vector<ProbedInstance> instances = {{furnace.cube, furnace.cube}};
  const ProbeBake paths = bakeIrradianceProbes(furnace.world.scene, furnace.world.geometry,
                                               *furnace.world.kernel, instances, settings);
  settings.cache = &cache;
  const ProbeBake cached = bakeIrradianceProbes(furnace.world.scene, furnace.world.geometry,
                                                *furnace.world.kernel, instances, settings);
  ASSERT_EQ(cached.probes.probes.size(), paths.probes.probes.size());
  int valid = 0;
  double squaredCached = 0.0, squaredPaths = 0.0;  // (E(n) − exact)², W²/m⁴
  for (std::size_t i = 0; i < cached.probes.probes.size(); ++i) {
    if (cached.invalid[i] || !cached.needed[i]) continue;
    ++valid;
    for (const glm::vec3& n : testNormals()) {
      const double e = luminance(probeIrradianceAt(cached.probes.probes[i], n));
      EXPECT_NEAR(e, exact, 5.0 * cached.relativeError[i] * exact + 1e-9) << "probe " << i;
      squaredCached += (e - exact) * (e - exact);
      const double p = luminance(probeIrradianceAt(paths.probes.probes[i], n));
      squaredPaths += (p - exact) * (p - exact);
    }
  }
  ASSERT_GT(valid, 0);
  std::printf("rms error, cached %.5f, whole paths %.5f W/m^2 (%d probes, %llu / %llu samples)\n",
              std::sqrt(squaredCached / valid), std::sqrt(squaredPaths / valid), valid,
              static_cast<unsigned long long>(cached.totalSamples),
              static_cast<unsigned long long>(paths.totalSamples));
  EXPECT_LT(squaredCached, 0.25 * squaredPaths);
}

// An error floor (ProbeSettings::errorFloor, W/m²; the bake sets it from --error-floor and the
// delivered map): a probe at or above it is untouched, the same samples and bytes as without;
// one below it stops once its standard error is under target × floor, so sooner, and lies
// within 5 of those errors of the furnace's exact light.
TEST(IrradianceProbes, AnErrorFloorStopsOnlyProbesDimmerThanItAtItsAbsoluteError) {
  const float rho = 0.5f, le = 1.0f;
  const FurnaceWithCube furnace(rho, le);
  const double exact = kPi * le * rho / (1.0 - rho);
  ProbeSettings settings;
  settings.maxSpp = 2048;
  settings.targetError = 0.1f;
  settings.seed = 5;
  const std::vector<ProbedInstance> instances = {{furnace.cube, furnace.cube}};
  auto bakeWithFloor = [&](double floor) {
    settings.errorFloor = floor;
    return bakeIrradianceProbes(furnace.world.scene, furnace.world.geometry, *furnace.world.kernel,
                                instances, settings);
  };
  const ProbeBake none = bakeWithFloor(0.0), below = bakeWithFloor(0.5 * exact),
                  above = bakeWithFloor(10.0 * exact);
  // Premise: without a floor the probes stop on their own error, before the cap.
  ASSERT_LT(*std::min_element(
                none.samples.begin(), none.samples.end(),
                [](uint32_t a, uint32_t b) { return (a == 0 ? ~0u : a) < (b == 0 ? ~0u : b); }),
            static_cast<uint32_t>(settings.maxSpp));
  EXPECT_EQ(below.samples, none.samples);
  EXPECT_EQ(below.probes.probes, none.probes.probes);
  int dim = 0;
  for (std::size_t i = 0; i < above.samples.size(); ++i) {
    if (above.invalid[i] || !above.needed[i]) continue;
    ++dim;
    EXPECT_LT(above.samples[i], none.samples[i]) << "probe " << i;
    EXPECT_LT(above.relativeError[i], settings.targetError) << "probe " << i;
    for (const glm::vec3& n : testNormals())
      EXPECT_NEAR(luminance(probeIrradianceAt(above.probes.probes[i], n)), exact,
                  5.0 * settings.targetError * 10.0 * exact)
          << "probe " << i;
  }
  EXPECT_GT(dim, 0);
}

// One instance of two 10 cm cubes 4 m apart (as the Conference Room's chairs are one mesh): the
// grid spans both at the largest spacing, 25 cm, and only the probes around the cubes are read.
TEST(IrradianceProbes, AnInstanceOfSmallPiecesFarApartIsProbedAroundThePiecesOnly) {
  test::World world;
  const uint32_t m = test::addMaterial(world.scene, glm::vec3(0.5f), glm::vec3(0.0f));
  Mesh mesh;
  mesh.name = "pieces";
  mesh.material = m;
  appendOutwardCube(mesh, {0.0f, 0.0f, 0.0f}, {0.1f, 0.1f, 0.1f});
  appendOutwardCube(mesh, {3.9f, 0.0f, 0.0f}, {4.0f, 0.1f, 0.1f});
  world.scene.meshes.push_back(mesh);
  world.scene.instances.push_back(Instance{.name = "pieces", .mesh = 0});
  world.build();
  const std::vector<ProbedInstance> instances = {{0, 0}};
  const std::vector<ProbeGrid> grids = placeProbeGrids(world.geometry, instances);
  ASSERT_EQ(grids.size(), 1u);
  EXPECT_NEAR(grids[0].spacing.x, kMaxProbeSpacing, 0.01f);
  EXPECT_EQ(grids[0].counts.y, 2u);
  const std::vector<uint8_t> needed = neededProbes(world.geometry, instances, grids);
  ASSERT_EQ(needed.size(), grids[0].probeCount());
  for (uint32_t z = 0; z < grids[0].counts.z; ++z)
    for (uint32_t y = 0; y < grids[0].counts.y; ++y)
      for (uint32_t x = 0; x < grids[0].counts.x; ++x) {
        const float px = grids[0].position({x, y, z}).x;
        // Within a cell of either cube (its box grown by the normal offset), else not read.
        const float reach = grids[0].spacing.x + grids[0].normalOffset;
        const bool near = px < 0.1f + reach || px > 3.9f - reach;
        EXPECT_EQ(needed[x + grids[0].counts.x * (y + grids[0].counts.y * z)] != 0, near)
            << "x = " << px;
      }
}

// Every probe is a function of the scene, the settings and its index: the file's bytes are the
// same at any thread count.
TEST(IrradianceProbes, TheSameBytesAtAnyThreadCount) {
  const FurnaceWithCube furnace(0.5f, 1.0f);
  ProbeSettings settings;
  settings.maxSpp = 256;
  settings.targetError = 0.05f;
  const std::vector<ProbedInstance> instances = {{furnace.cube, furnace.cube}};
  settings.threads = 1;
  const ProbeBake one = bakeIrradianceProbes(furnace.world.scene, furnace.world.geometry,
                                             *furnace.world.kernel, instances, settings);
  settings.threads = 2;
  const ProbeBake two = bakeIrradianceProbes(furnace.world.scene, furnace.world.geometry,
                                             *furnace.world.kernel, instances, settings);
  EXPECT_EQ(encodeProbes(one.probes), encodeProbes(two.probes));
  EXPECT_EQ(one.samples, two.samples);
}

// The delivered map serves as a cache only where it holds no direct light: a baked-only light's
// or emitter's direct light is in the map, and the paths' next-event estimate at the cache's hit
// would count it a second time.
TEST(DeliveredMapCache, NoneWhereTheMapHoldsABakedOnlyLightsDirectLight) {
  test::World world;
  const uint32_t white = test::addMaterial(world.scene, glm::vec3(0.5f));
  test::addQuad(world.scene, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, white);
  world.build();
  LightmapLayout layout;
  layout.width = layout.height = 4;
  layout.texelSize = 0.25f;
  LightmapBake bake;
  bake.irradiance = Image(4, 4, glm::vec3(1.0f));
  bake.covered.assign(16, 1);
  bake.invalid.assign(16, 0);
  Scene& scene = world.scene;
  EXPECT_NE(deliveredMapCache(scene, world.geometry, layout, bake), nullptr);
  Light lamp;
  lamp.name = "lamp";
  scene.lights.push_back(lamp);
  EXPECT_NE(deliveredMapCache(scene, world.geometry, layout, bake), nullptr);  // drawn live
  scene.lights.back().bakeDirect = true;
  EXPECT_EQ(deliveredMapCache(scene, world.geometry, layout, bake), nullptr);
  scene.lights.clear();
  const uint32_t glow = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(2.0f));
  EXPECT_NE(deliveredMapCache(scene, world.geometry, layout, bake), nullptr);
  scene.materials[glow].bakeDirect = true;
  EXPECT_EQ(deliveredMapCache(scene, world.geometry, layout, bake), nullptr);
}

}  // namespace
}  // namespace bounce
