// The bake's VPLs with a placed object cutting their light paths (vpl_runtime/vpl_occlusion.h)
// against the generator run with that object in the scene. The object is black (albedo 0) in the
// reference run, so that paths reaching it end there, as they do when the mask cuts them: the
// two sets then estimate the same flux per bounce (the masked set lacks only the light the object
// reflects, here none). Tolerance: 4 standard errors of the difference of the two estimates,
// sqrt(se_masked² + se_reference²), each from its per-path contributions (the two share random
// numbers, which only makes the difference smaller).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "trace/test_scenes.h"
#include "vpl/vpl_generate.h"
#include "vpl_runtime/vpl_occlusion.h"

namespace bounce {
namespace {

using test::addInwardBox;
using test::addMaterial;
using test::addQuad;

constexpr int kPaths = 16384;
constexpr int kBounces = 3;

VplSettings fixedPaths() {
  VplSettings s;
  s.maxVpls = 1 << 22;
  s.minPaths = kPaths;
  s.relativeError = 1.0f;  // stop at minPaths
  s.seed = 11;
  return s;
}

// Σ flux (W, green) of the bounce-k VPLs with alive ≠ 0, and its standard error from the
// per-path contributions (N = set.paths estimates).
struct BounceSum {
  double flux = 0.0, error = 0.0;
};
BounceSum bounceSum(const VplSet& set, std::span<const uint8_t> alive, int k) {
  std::vector<double> perPath;  // the non-zero ones; the others contribute 0
  double sum = 0.0, sumSq = 0.0;
  double current = 0.0;
  for (std::size_t i = 0; i <= set.vpls.size(); ++i) {
    if (i == set.vpls.size() || (i > 0 && set.vpls[i].path != set.vpls[i - 1].path)) {
      sum += current;
      sumSq += current * current;
      current = 0.0;
      if (i == set.vpls.size()) break;
    }
    if (set.bounce[i] == k && alive[i] != 0) current += static_cast<double>(set.vpls[i].flux.g);
  }
  const double n = static_cast<double>(set.paths);
  BounceSum out;
  out.flux = sum;
  // The VPL fluxes are already divided by N: the path estimates are N·c, their mean Σc, whose
  // variance is Var(N·c)/N = N·Var(c).
  const double variance = std::max(0.0, sumSq - sum * sum / n) / (n - 1.0);  // Var(c)
  out.error = std::sqrt(variance * n);
  return out;
}

// A closed box of unequal albedo walls (red floor), an off-centre point light under the
// ceiling and a tilted quad occluder between it and the floor.
struct Room {
  test::World world;
  Mesh occluder;
  explicit Room(bool withBlackOccluder) {
    Scene& scene = world.scene;
    addInwardBox(scene, glm::vec3(-1.0f), glm::vec3(1.0f), addMaterial(scene, {0.6f, 0.5f, 0.4f}));
    addQuad(scene, {-1.0f, -0.999f, -1.0f}, {-1.0f, -0.999f, 1.0f}, {1.0f, -0.999f, 1.0f},
            {1.0f, -0.999f, -1.0f}, addMaterial(scene, {0.8f, 0.2f, 0.2f}));
    Light light;
    light.position = {0.25f, 0.8f, -0.15f};
    light.intensity = {1.0f, 2.0f, 3.0f};
    scene.lights.push_back(light);
    const uint32_t black = addMaterial(scene, glm::vec3(0.0f));
    addQuad(scene, {-0.5f, 0.1f, -0.45f}, {-0.45f, 0.3f, 0.5f}, {0.6f, 0.35f, 0.45f},
            {0.55f, 0.15f, -0.5f}, black);
    occluder = scene.meshes.back();
    if (!withBlackOccluder) scene.instances.pop_back();
    world.build();
  }
};

TEST(VplOcclusion, MaskedStaticVplsAgreeWithTheGeneratorRunWithTheOccluderPerBounce) {
  Room open(false), blocked(true);
  const VplSet set =
      generateVpls(open.world.scene, open.world.geometry, *open.world.kernel, fixedPaths());
  const VplSet reference = generateVpls(blocked.world.scene, blocked.world.geometry,
                                        *blocked.world.kernel, fixedPaths());
  const VplOccluder occluder = makeVplOccluder(open.occluder, glm::mat4(1.0f));
  const std::vector<uint8_t> alive = vplAliveMask(set.vpls, std::span(&occluder, 1));
  const std::vector<uint8_t> all(set.vpls.size(), 1);
  const std::vector<uint8_t> allRef(reference.vpls.size(), 1);
  for (int k = 1; k <= kBounces; ++k) {
    const BounceSum masked = bounceSum(set, alive, k);
    const BounceSum unmasked = bounceSum(set, all, k);
    const BounceSum truth = bounceSum(reference, allRef, k);
    const double tolerance = 4.0 * std::hypot(masked.error, truth.error);
    std::printf("bounce %d: masked %.5f ± %.5f W, occluder traced %.5f ± %.5f W, unmasked %.5f W\n",
                k, masked.flux, masked.error, truth.flux, truth.error, unmasked.flux);
    EXPECT_NEAR(masked.flux, truth.flux, tolerance) << "bounce " << k;
    // The occluder must matter far beyond the tolerance, or the comparison shows nothing.
    EXPECT_GT(unmasked.flux - truth.flux, 3.0 * tolerance) << "bounce " << k;
  }
}

TEST(VplOcclusion, ABlockedSegmentDarkensItsVplAndTheRestOfItsPathOnly) {
  // Two paths of three VPLs along x; a wall at x = 1.5 (a quad facing -x) crosses path 0's
  // second segment only.
  std::vector<Vpl> vpls;
  for (uint32_t path = 0; path < 2; ++path)
    for (int k = 0; k < 3; ++k) {
      Vpl v;
      const float y = path == 0 ? 0.0f : 5.0f;
      v.from = {static_cast<float>(k), y, 0.0f};
      v.position = {static_cast<float>(k + 1), y, 0.0f};
      v.path = path;
      vpls.push_back(v);
    }
  Mesh wall;
  wall.positions = {{1.5f, -1, -1}, {1.5f, 1, -1}, {1.5f, 1, 1}, {1.5f, -1, 1}};
  wall.indices = {0, 1, 2, 0, 2, 3};
  const VplOccluder occluder = makeVplOccluder(wall, glm::mat4(1.0f));
  EXPECT_EQ(vplAliveMask(vpls, std::span(&occluder, 1)), (std::vector<uint8_t>{1, 0, 0, 1, 1, 1}));
  // Moved (object → world) past path 0's end: nothing blocked.
  const VplOccluder moved =
      makeVplOccluder(wall, glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f)));
  EXPECT_EQ(vplAliveMask(vpls, std::span(&moved, 1)), std::vector<uint8_t>(6, 1));
}

// The generator's record of the light paths: a bounce-1 VPL's segment starts at the (point)
// light, a later one's at the previous VPL of the same path; paths are consecutive and in order.
TEST(VplOcclusion, GeneratorRecordsEachVplsPathAndSegmentStart) {
  Room room(false);
  VplSettings settings = fixedPaths();
  settings.minPaths = 1024;
  const VplSet set =
      generateVpls(room.world.scene, room.world.geometry, *room.world.kernel, settings);
  ASSERT_GT(set.vpls.size(), 1024u);
  const glm::vec3 light = room.world.scene.lights[0].position;
  for (std::size_t i = 0; i < set.vpls.size(); ++i) {
    const Vpl& v = set.vpls[i];
    ASSERT_LT(v.path, set.paths);
    if (set.bounce[i] == 1) {
      EXPECT_EQ(v.from, light) << "VPL " << i;
      if (i > 0) {
        EXPECT_GT(v.path, set.vpls[i - 1].path) << "VPL " << i;
      }
    } else {
      ASSERT_GT(i, 0u);
      EXPECT_EQ(set.bounce[i], set.bounce[i - 1] + 1) << "VPL " << i;
      EXPECT_EQ(v.path, set.vpls[i - 1].path) << "VPL " << i;
      EXPECT_EQ(v.from, set.vpls[i - 1].position) << "VPL " << i;
    }
  }
}

}  // namespace
}  // namespace bounce
