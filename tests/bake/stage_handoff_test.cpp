// The hand-offs between bakeLightmap's stages, each checked where the next stage reads it:
//   coverage → irradiance: a texel's sample points are spread over its surface by clipped area,
//     so a texel cut 0.9 / 0.1 between a lit and a black triangle bakes to 0.9·E;
//   irradiance → denoiser: the caller's guide keeps charts apart (their labels) and carries the
//     per-texel error, so two charts side by side with different exact irradiance keep their
//     own values after denoising, and the noise inside a chart goes down.
// Each stage's own unit test (coverage_test.cpp, filters_test.cpp) can pass while the caller
// hands the next stage the wrong thing; these tests run the whole bake.
#include <gtest/gtest.h>

#include <cmath>

#include "bake/texel_coverage.h"
#include "bake_scenes.h"
#include "trace/sampling.h"

namespace bounce {
namespace {

// Texel-space image of a rectangle instance (p0 p1 p2 p3, indices 0 1 2 0 2 3): corner k of
// the rectangle goes to corner[k].
InstanceLightmapUv rectangleRegion(const Scene& scene, uint32_t instance,
                                   const std::array<glm::vec2, 4>& corner, glm::vec2 atlasSize) {
  InstanceLightmapUv region;
  region.instance = instance;
  for (const uint32_t index : scene.meshes[scene.instances[instance].mesh].indices)
    region.cornerUv.push_back(corner[index] / atlasSize);
  return region;
}

// A black horizontal quad L (y = 0, facing +y) under a directional light marked baked-only
// (straight down, E = `irradiance` W/m² on L), and a black vertical quad D (x = 2, facing −x,
// towards L) that the light grazes (cos θ = 0: E = 0). Both albedos are 0, so nothing reflects:
// the map holds the direct light alone, E on L and 0 on D, with no noise.
// In a 10×8 atlas L's image is [2, 5.9] × [2, 6] and D's [5.9, 8] × [2, 6]: the four texels of
// column 5 are cut 0.9 (L) / 0.1 (D).
struct CutTexelScene {
  test::World world;
  LightmapLayout layout;
  glm::vec3 irradiance{2.0f, 1.0f, 0.5f};
  static constexpr float kCut = 5.9f;
  static constexpr int kCutColumn = 5;

  CutTexelScene() {
    const uint32_t black = test::addMaterial(world.scene, glm::vec3(0.0f));
    test::addQuad(world.scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, black);  // L, +y
    test::addQuad(world.scene, {2, 0, 0}, {2, 0, 1}, {2, 1, 1}, {2, 1, 0}, black);  // D, −x
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0};
    sun.irradiance = irradiance;
    sun.bakeDirect = true;
    world.scene.lights.push_back(sun);
    world.build();
    layout.width = 10;
    layout.height = 8;
    layout.padding = 2;
    layout.texelSize = 0.25f;
    layout.chartCount = 2;
    const glm::vec2 size(10.0f, 8.0f);
    // L: world (x, z) → texel (2 + 3.9x, 2 + 4z); D: world (y, z) → texel (5.9 + 2.1y, 2 + 4z).
    layout.instances.push_back(
        rectangleRegion(world.scene, 0, {{{2, 2}, {2, 6}, {kCut, 6}, {kCut, 2}}}, size));
    layout.instances.push_back(
        rectangleRegion(world.scene, 1, {{{kCut, 2}, {kCut, 6}, {8, 6}, {8, 2}}}, size));
  }
};

// With N points drawn by area from a stratified (0,2)-sequence, the share of points on L in a
// cut texel is the share of N strata of [0, 1) that fall below 0.9 (L's fan triangles come first
// in the area-weighted pick), off by at most one stratum: |share − 0.9| ≤ 1/N.
TEST(StageHandoff, CoveragePointsSplitACutTexelByClippedArea) {
  const CutTexelScene s;
  const int points = 64;
  const TexelCoverage coverage =
      buildTexelCoverage(s.world.scene, s.world.geometry, s.layout, points, 11);
  for (int y = 2; y < 6; ++y) {
    const std::size_t t = static_cast<std::size_t>(y) * s.layout.width + CutTexelScene::kCutColumn;
    ASSERT_EQ(coverage.pointCount(t), static_cast<uint32_t>(points));
    EXPECT_NEAR(coverage.coveredArea[t], 1.0f, 1e-5f);
    int onL = 0;
    for (uint32_t k = coverage.first[t]; k < coverage.first[t + 1]; ++k)
      onL += coverage.points[k].geometricNormal.y > 0.5f ? 1 : 0;
    EXPECT_NEAR(static_cast<double>(onL) / points, 0.9, 1.0 / points + 1e-9) << "row " << y;
  }
}

// The bake of the cut texels: 64 samples pick each of the 64 points once (stratified pick), each
// worth E (on L) or 0 (on D) exactly, so the texel holds (share on L)·E, |share − 0.9| ≤ 1/64.
// Texels wholly on L hold E, those wholly on D hold 0.
TEST(StageHandoff, TexelCutBetweenALitAndABlackTriangleBakesToTheLitShare) {
  const CutTexelScene s;
  LightmapBakeSettings settings = test::testBakeSettings(64);
  settings.pointsPerTexel = 64;
  const LightmapBake bake =
      bakeLightmap(s.world.scene, s.world.geometry, *s.world.kernel, s.layout, settings);
  // No point was dropped: L and D see each other and no probe meets a back face.
  EXPECT_EQ(bake.pointsInside, 0u);
  EXPECT_EQ(bake.pointsAcross, 0u);
  const float tolerance = 1.0f / 64.0f + 1e-5f;
  for (int y = 2; y < 6; ++y) {
    for (int x = 2; x < 8; ++x) {
      const glm::vec3 e = bake.irradiance.at(x, y);
      const float share = x < CutTexelScene::kCutColumn    ? 1.0f
                          : x == CutTexelScene::kCutColumn ? 0.9f
                                                           : 0.0f;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e[c] / s.irradiance[c], share, tolerance) << x << "," << y << " channel " << c;
    }
  }
}

// Two closed boxes (0.25 × 0.25 × 1.5 m) side by side, 2 mm apart, every face of albedo ρ
// emitting Le: inside each the indirect irradiance is π·Le·ρ/(1 − ρ) everywhere
// (BakePhysics.FurnaceIndirectIrradianceIsExact). Le differs between the boxes, so their floors,
// coplanar and 2 mm apart in the world, differ by half of A's value. Their charts lie 3 texels
// apart in the atlas (the usual padding of 2), edge to edge as in the world, within the denoiser's
// reach (steps 2 and 4 at 1.25 cm texels).
struct TwoFurnaces {
  test::World world;
  LightmapLayout layout;
  static constexpr float kSide = 0.25f, kDepth = 1.5f, kGap = 0.002f, kTexel = 0.0125f;
  static constexpr float kRho = 0.5f, kLeA = 1.0f, kLeB = 1.5f;
  static constexpr int kTexels = 20, kRows = 120;  // a floor's texels across (x) and along (z)
  static constexpr int kOriginA = 2, kOriginB = 2 + kTexels + 2;
  static constexpr uint32_t kFloorA = 4, kFloorB = 10;  // addInwardBox's y = lo face

  TwoFurnaces() {
    const uint32_t a = test::addMaterial(world.scene, glm::vec3(kRho), glm::vec3(kLeA));
    const uint32_t b = test::addMaterial(world.scene, glm::vec3(kRho), glm::vec3(kLeB));
    test::addInwardBox(world.scene, glm::vec3(0.0f), glm::vec3(kSide, kSide, kDepth), a);
    test::addInwardBox(world.scene, glm::vec3(kSide + kGap, 0, 0),
                       glm::vec3(2 * kSide + kGap, kSide, kDepth), b);
    world.build();
    layout.width = kOriginB + kTexels + 2;
    layout.height = 2 + kRows + 2;
    layout.padding = 2;
    layout.texelSize = kTexel;
    layout.chartCount = 2;
    const glm::vec2 size(static_cast<float>(layout.width), static_cast<float>(layout.height));
    // World (x, z) on a floor → texel (origin + (x − x0)/texel, 2 + z/texel).
    for (const auto& [floor, origin, x0] :
         {std::tuple{kFloorA, kOriginA, 0.0f}, std::tuple{kFloorB, kOriginB, kSide + kGap}}) {
      InstanceLightmapUv region;
      region.instance = floor;
      const Mesh& mesh = world.scene.meshes[world.scene.instances[floor].mesh];
      for (const uint32_t index : mesh.indices) {
        const glm::vec3 p = mesh.positions[index];
        region.cornerUv.push_back(
            glm::vec2(static_cast<float>(origin) + (p.x - x0) / kTexel, 2.0f + p.z / kTexel) /
            size);
      }
      layout.instances.push_back(region);
    }
  }
  static double exact(float le) { return kPi * le * kRho / (1.0 - kRho); }
};

struct BandMean {
  double mean = 0;           // mean of luminance over the band's texels
  double standardError = 0;  // sqrt(Σ se²)/n, se = relativeError · value (the raw estimates')
  double spread = 0;         // sample standard deviation of the texel values
};

BandMean bandMean(const LightmapBake& bake, int x0, int x1) {
  BandMean band;
  double sum = 0, sum2 = 0, variance = 0;
  int n = 0;
  for (int y = 2; y < 2 + TwoFurnaces::kRows; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const std::size_t t = bake.irradiance.index(x, y);
      EXPECT_TRUE(bake.covered[t] && !bake.invalid[t]) << x << "," << y;
      const double e = luminance(bake.irradiance.pixels[t]);
      const double se = bake.relativeError[t] * e;
      sum += e;
      sum2 += e * e;
      variance += se * se;
      ++n;
    }
  }
  band.mean = sum / n;
  band.standardError = std::sqrt(variance) / n;
  band.spread = std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1)));
  return band;
}

// Denoised, the two columns of each floor next to the other floor keep their own box's exact
// irradiance: within 5 standard errors of the band's mean (a weighted mean of unbiased texel
// estimates of one value is unbiased; smoothing only shrinks its variance), and so does the
// difference of the two bands' relative deviations, which a blend of the floors moves most (A up,
// B down): a denoiser handed one chart label for every texel moves it by about 18%, 9 of its
// standard errors. Without the denoiser, the same holds of the raw estimates.
TEST(StageHandoff, DenoiserKeepsTwoChartsSideBySideApart) {
  const TwoFurnaces s;
  const double exactA = TwoFurnaces::exact(TwoFurnaces::kLeA);
  const double exactB = TwoFurnaces::exact(TwoFurnaces::kLeB);
  double rawSpread = 0;
  for (const bool denoise : {false, true}) {
    LightmapBakeSettings settings = test::testBakeSettings(16);
    settings.denoise = denoise;
    const LightmapBake bake =
        bakeLightmap(s.world.scene, s.world.geometry, *s.world.kernel, s.layout, settings);
    const int a1 = TwoFurnaces::kOriginA + TwoFurnaces::kTexels - 1;
    const BandMean nearA = bandMean(bake, a1 - 1, a1);
    const BandMean nearB = bandMean(bake, TwoFurnaces::kOriginB, TwoFurnaces::kOriginB + 1);
    EXPECT_NEAR(nearA.mean, exactA, 5.0 * nearA.standardError)
        << "denoise " << denoise << ", standard error " << nearA.standardError;
    EXPECT_NEAR(nearB.mean, exactB, 5.0 * nearB.standardError)
        << "denoise " << denoise << ", standard error " << nearB.standardError;
    const double seA = nearA.standardError / exactA, seB = nearB.standardError / exactB;
    EXPECT_NEAR(nearA.mean / exactA - nearB.mean / exactB, 0.0,
                5.0 * std::sqrt(seA * seA + seB * seB))
        << "denoise " << denoise;
    // The denoiser did smooth (the guide carries each texel's error and its world position): a
    // 5×5 B3-spline pass alone scales white noise's deviation by Σb² = 0.27, and three passes
    // with edge-stopping at 1.5 standard errors leave well under a quarter of the raw bake's
    // texel-to-texel deviation over floor A.
    const double spread = bandMean(bake, TwoFurnaces::kOriginA, a1).spread;
    if (!denoise)
      rawSpread = spread;
    else
      EXPECT_LT(spread, 0.25 * rawSpread) << "raw " << rawSpread;
  }
}

}  // namespace
}  // namespace bounce
