// The renderer's VPL term (shaders/vpl.glsl) against the CPU gather (baker/vpl/vpl_gather.h) at
// every pixel of a small offscreen frame (OSMesa): a floor seen from above, lit by VPLs on a
// wall beside it (some millimetres above the floor, inside the clamp distance) and on a tilted
// panel over it, with unequal coloured fluxes. vpl mode: L = ρ/π · E_vpl, clamped and unclamped;
// vpl-clamp mode: the removed part; with culling, the GPU cut equals the CPU mirror of the same
// cut (vplCutIrradiance); a dynamic instance in indirect mode gets the same VPL light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "image/luminance.h"
#include "lightmap_scenes.h"
#include "render/vpl_pass.h"
#include "test_scenes.h"
#include "vpl/vpl_gather.h"
#include "vpl_runtime/vpl_groups.h"

namespace bounce::test {
namespace {

constexpr double kPi = 3.14159265358979;
constexpr int kSize = 32;
const glm::vec3 kAlbedo{0.8f, 0.5f, 0.9f};

struct VplScene {
  Scene scene;
  Camera camera = downCamera(1.0f);
  std::vector<Vpl> vpls;
};

VplScene vplScene(Mobility floorMobility) {
  VplScene s;
  Material floor;
  floor.name = "floor";
  floor.albedo = kAlbedo;
  addQuad(s.scene, {-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, floor);
  s.scene.instances[0].mobility = floorMobility;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // A wall at x = −0.45 facing +x, from 2 mm to 0.4 m above the floor: the lowest VPLs lie
  // within the clamp distance of the floor pixels next to the wall.
  for (int i = 0; i < 150; ++i) {
    Vpl v;
    v.position = {-0.45f, 0.002f + 0.4f * u(rng) * u(rng), -0.45f + 0.9f * u(rng)};
    v.normal = {1, 0, 0};
    v.flux = glm::vec3(0.9f, 0.2f, 0.1f) * (1e-3f * (0.2f + u(rng)));
    s.vpls.push_back(v);
  }
  // A panel 0.3 m up, tilted 30° about x, facing down.
  const glm::vec3 n = glm::normalize(glm::vec3(0.0f, -std::cos(0.52f), std::sin(0.52f)));
  for (int i = 0; i < 100; ++i) {
    Vpl v;
    v.position = {-0.2f + 0.5f * u(rng), 0.3f + 0.1f * u(rng), -0.2f + 0.3f * u(rng)};
    v.normal = n;
    v.flux = glm::vec3(0.1f, 0.4f, 0.8f) * (1e-3f * (0.2f + u(rng)));
    s.vpls.push_back(v);
  }
  return s;
}

Bake vplBake(const VplScene& s, float clampDistance) {
  Bake bake;
  bake.layout.width = bake.layout.height = 1;
  bake.layout.texelSize = 1.0f;
  bake.irradiance = Image(1, 1);
  bake.manifest = minimalManifest(s.scene);
  bake.manifest.vpls = BakeManifest::Vpls{.count = s.vpls.size(), .clampDistance = clampDistance};
  bake.vpls = s.vpls;
  return bake;
}

Image renderVpls(const VplScene& s, const Bake& bake, RenderMode mode, bool culling) {
  testContext();
  RendererSettings settings;
  settings.mode = mode;
  settings.vpls.culling = culling;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &bake);
  return renderer.renderImage(s.camera, kSize, kSize);
}

// |a − b| ≤ 1e-4·|b| + 1e-7 + spread per channel: float evaluation of the same sum in another
// order, and what the CPU value changes by over the rasterizer's sub-pixel step (`spread`,
// subpixelSpread below): the GPU's floor point is interpolated, not the pixel centre's exactly.
void expectClose(glm::vec3 gpu, glm::dvec3 cpu, glm::dvec3 spread, int x, int y, const char* what) {
  for (int c = 0; c < 3; ++c)
    ASSERT_NEAR(gpu[c], cpu[c], 1e-4 * std::abs(cpu[c]) + 1e-7 + spread[c])
        << what << " pixel (" << x << ", " << y << ") channel " << c << " (sub-pixel spread "
        << spread[c] << ")";
}

// The largest change of f (a CPU value at a floor point) from pixel (x, y)'s centre to the floor
// points one sub-pixel step away (test_scenes.h: subpixelOffsets).
template <class F>
glm::dvec3 subpixelSpread(const VplScene& s, int x, int y, F f) {
  const glm::dvec3 centre = f(floorPoint(s.camera, kSize, kSize, x, y));
  glm::dvec3 spread(0.0);
  for (const glm::vec2 o : subpixelOffsets(testContext())) {
    const glm::vec3 p = floorPoint(s.camera, kSize, kSize, static_cast<float>(x) + 0.5f + o.x,
                                   static_cast<float>(y) + 0.5f + o.y);
    spread = glm::max(spread, glm::abs(f(p) - centre));
  }
  return spread;
}

class VplRender : public testing::TestWithParam<float> {};

TEST_P(VplRender, EveryPixelIsReflectanceOverPiTimesTheCpuGather) {
  const float r = GetParam();
  const VplScene s = vplScene(Mobility::Static);
  const Bake bake = vplBake(s, r);
  const Image image = renderVpls(s, bake, RenderMode::Vpl, false);
  const Image clampImage = renderVpls(s, bake, RenderMode::VplClamp, false);
  double removedTotal = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto reflected = [&](glm::vec3 p) {
        return glm::dvec3(kAlbedo) / kPi *
               gatherVplIrradiance(s.vpls, p, {0, 1, 0}, nullptr, r).irradiance;
      };
      const auto clampView = [&](glm::vec3 p) {
        const VplIrradiance e = gatherVplIrradiance(s.vpls, p, {0, 1, 0}, nullptr, r);
        return glm::dvec3(luminance(e.irradiance), luminance(e.removed), 0.0) / kPi;
      };
      const glm::vec3 p = floorPoint(s.camera, kSize, kSize, x, y);
      const std::size_t i = static_cast<std::size_t>(y) * kSize + x;
      expectClose(image.pixels[i], reflected(p), subpixelSpread(s, x, y, reflected), x, y, "vpl");
      expectClose(clampImage.pixels[i], clampView(p), subpixelSpread(s, x, y, clampView), x, y,
                  "vpl-clamp");
      removedTotal += clampView(p).y * kPi;
    }
  // The clamped case must remove something (VPLs within r of the floor), the other nothing.
  if (r > 0.0f)
    EXPECT_GT(removedTotal, 0.0);
  else
    EXPECT_EQ(removedTotal, 0.0);
}

// ForwardRenderer::measureVplClamp sums the vpl-clamp view: Σ lum(E_vpl) and Σ lum(E_removed)
// over the pixels (W/m²), as the CPU gather gives them.
TEST(VplRender, ClampReportSumsTheFrame) {
  const VplScene s = vplScene(Mobility::Static);
  const float r = 0.05f;
  const Bake bake = vplBake(s, r);
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  settings.vpls.culling = false;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &bake);
  const VplClampReport report = renderer.measureVplClamp(s.camera, kSize, kSize);
  EXPECT_EQ(renderer.settings().mode, RenderMode::Vpl);
  EXPECT_EQ(report.vplCount, s.vpls.size());
  EXPECT_EQ(report.clampDistance, r);
  // Per pixel, the float rounding (1e-4) and the sub-pixel spread of each sum, added up.
  double irradiance = 0.0, removed = 0.0, irradianceSpread = 0.0, removedSpread = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto sums = [&](glm::vec3 p) {
        const VplIrradiance e = gatherVplIrradiance(s.vpls, p, {0, 1, 0}, nullptr, r);
        return glm::dvec3(luminance(e.irradiance), luminance(e.removed), 0.0);
      };
      const glm::dvec3 e = sums(floorPoint(s.camera, kSize, kSize, x, y));
      const glm::dvec3 spread = subpixelSpread(s, x, y, sums);
      irradiance += e.x;
      removed += e.y;
      irradianceSpread += spread.x;
      removedSpread += spread.y;
    }
  EXPECT_NEAR(report.irradiance, irradiance, 1e-4 * irradiance + irradianceSpread);
  EXPECT_NEAR(report.removed, removed, 1e-4 * removed + removedSpread);
  const double fraction = removed / (irradiance + removed);
  EXPECT_NEAR(report.removedFraction(), fraction,
              1e-4 + (removedSpread + fraction * (irradianceSpread + removedSpread)) /
                         (irradiance + removed));
  EXPECT_GT(report.removedFraction(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(ClampedAndUnclamped, VplRender, testing::Values(0.05f, 0.0f));

// The viewer's VPL controls (ForwardRenderer::setVplSelection): the first P of the bake's N light
// paths, each VPL's flux × N/P, clamped at another r, give at every pixel ρ/π times the CPU
// gather of exactly those VPLs (built here from the definition, not by vpl_paths.h) at that r;
// P = N at the bake's r is the bake's frame bit for bit.
TEST(VplRender, SelectedPathsAndClampAreTheCpuGatherOfThoseVpls) {
  VplScene s = vplScene(Mobility::Static);
  for (std::size_t i = 0; i < s.vpls.size(); ++i) s.vpls[i].path = static_cast<uint32_t>(i / 2);
  const uint64_t totalPaths = 130;  // 125 left VPLs, the last 5 escaped
  Bake bake = vplBake(s, 0.05f);
  bake.manifest.vpls->paths = totalPaths;
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  settings.vpls.culling = false;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &bake);
  const Image whole = renderer.renderImage(s.camera, kSize, kSize);

  const uint64_t paths = 90;  // every wall VPL (paths 0..74) and part of the panel's
  const float r = 0.12f;
  renderer.setVplSelection(paths, r);
  const ForwardRenderer::VplSelection selection = renderer.vplSelection();
  EXPECT_EQ(selection.paths, paths);
  EXPECT_EQ(selection.totalPaths, totalPaths);
  EXPECT_EQ(selection.vplCount, 2 * paths);
  EXPECT_EQ(selection.clampDistance, r);
  EXPECT_EQ(selection.bakeClampDistance, 0.05f);
  std::vector<Vpl> expected;
  for (const Vpl& vpl : s.vpls)
    if (vpl.path < paths) {
      expected.push_back(vpl);
      expected.back().flux *= static_cast<float>(totalPaths) / static_cast<float>(paths);
    }
  const Image image = renderer.renderImage(s.camera, kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto reflected = [&](glm::vec3 p) {
        return glm::dvec3(kAlbedo) / kPi *
               gatherVplIrradiance(expected, p, {0, 1, 0}, nullptr, r).irradiance;
      };
      expectClose(image.at(x, y), reflected(floorPoint(s.camera, kSize, kSize, x, y)),
                  subpixelSpread(s, x, y, reflected), x, y, "selected VPLs");
    }
  renderer.setVplSelection(totalPaths, 0.05f);
  EXPECT_TRUE(renderer.renderImage(s.camera, kSize, kSize).pixels == whole.pixels);
  EXPECT_THROW(renderer.setVplSelection(paths, -1.0f), std::invalid_argument);
}

TEST(VplRender, CulledFrameIsTheCpuCut) {
  const VplScene s = vplScene(Mobility::Static);
  const float r = 0.05f;
  const Bake bake = vplBake(s, r);
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &bake);
  const Image image = renderer.renderImage(s.camera, kSize, kSize);
  const VplGroups& groups = renderer.vpls().groups();
  const VplLightCuts& cuts = renderer.vpls().cuts();
  ASSERT_GT(groups.groupCount(), 1u);
  // The cut is in use (not the one-cell fallback) and leaves VPLs out somewhere.
  ASSERT_GT(cuts.cellEntries.size(), 1u);
  std::size_t fewest = s.vpls.size();
  for (std::size_t c = 0; c < cuts.cellEntries.size(); ++c)
    fewest = std::min(fewest, cuts.lightsEvaluated(c));
  EXPECT_LT(fewest, s.vpls.size() / 2);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto reflected = [&](glm::vec3 p) {
        return glm::dvec3(kAlbedo) / kPi *
               vplCutIrradiance(groups, cuts, p, {0, 1, 0}, r).irradiance;
      };
      expectClose(image.pixels[static_cast<std::size_t>(y) * kSize + x],
                  reflected(floorPoint(s.camera, kSize, kSize, x, y)),
                  subpixelSpread(s, x, y, reflected), x, y, "culled vpl");
    }
}

// A dynamic instance takes its indirect light from the VPLs in the indirect mode: the same
// frame as the vpl mode.
// The floor (with `mobility`, no lightmap region in the bake) in indirect mode is the VPL frame.
void expectIndirectIsTheVplFrame(Mobility mobility) {
  const VplScene s = vplScene(mobility);
  const Bake bake = vplBake(s, 0.05f);
  const Image vpl = renderVpls(s, bake, RenderMode::Vpl, true);
  const Image indirect = renderVpls(s, bake, RenderMode::Indirect, true);
  double sum = 0.0;
  for (std::size_t i = 0; i < vpl.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) ASSERT_EQ(indirect.pixels[i][c], vpl.pixels[i][c]) << i;
    sum += vpl.pixels[i].r;
  }
  EXPECT_GT(sum, 0.0);
}

TEST(VplRender, DynamicInstanceInIndirectModeGetsTheVpls) {
  expectIndirectIsTheVplFrame(Mobility::Dynamic);
}

// A static instance the atlas left without a region (too small for a lightmap, or
// lightmapScale 0: atlas/atlas.h), in a bake without irradiance probes for it (this one is made
// by hand), takes the VPLs' light as a dynamic one does, in full and indirect alike (without the
// rule it read no indirect light at all).
TEST(VplRender, StaticInstanceWithoutALightmapRegionGetsTheVpls) {
  expectIndirectIsTheVplFrame(Mobility::Static);
}

TEST(VplRender, VplModeWithoutVplsNamesTheReason) {
  VplScene s = vplScene(Mobility::Static);
  s.vpls.clear();
  Bake bake = vplBake(s, 0.05f);
  bake.vpls.reset();
  testContext();
  RendererSettings settings;
  settings.mode = RenderMode::Vpl;
  try {
    ForwardRenderer renderer(s.scene, gl::shaderDirectory(), settings, &bake);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("virtual point lights"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bounce::test
