// bounce-bake writes the VPLs into the bake folder: content/point_over_plane (a 4 m plane of
// ρ = 0.5, a 1 W/sr point light 1 m above its centre) has one bounce only, whose flux is
// ρ·I·Ω with Ω = 4·asin(a²/(a² + h²)) = 4·asin(4/5) sr the solid angle of the plane (a = 2 m,
// h = 1 m). bake.json's count and total flux must describe the vpls file exactly; the total
// must match the closed form within 5 of the relative standard errors bake.json reports.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "bake_folder/bake_folder.h"
#include "scene/load.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;

TEST(VplBakeApp, PointOverPlaneVplsMatchTheManifestAndTheClosedForm) {
  const fs::path scene =
      fs::path(BOUNCE_SOURCE_DIR) / "content/point_over_plane/point_over_plane.gltf";
  const fs::path out = fs::temp_directory_path() / "bounce_vpl_bake_app_test.bake";
  fs::remove_all(out);
  const std::string command = std::string(BOUNCE_BIN_DIR) + "/bounce-bake '" + scene.string() +
                              "' -o '" + out.string() +
                              "' --quiet --spp 16 --texel-budget 1024 --vpls 3000 --vpl-error 0.01";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Scene loaded = loadScene(scene);
  const Bake bake = readBake(out, loaded);
  ASSERT_TRUE(bake.vpls.has_value());
  ASSERT_TRUE(bake.manifest.vpls.has_value());
  const BakeManifest::Vpls& v = *bake.manifest.vpls;
  EXPECT_EQ(v.count, bake.vpls->size());
  EXPECT_LE(bake.vpls->size(), 3000u);
  glm::dvec3 sum(0.0);
  for (const Vpl& vpl : *bake.vpls) {
    sum += glm::dvec3(vpl.flux);
    EXPECT_NEAR(vpl.position.y, 0.0f, 1e-5f) << "a VPL off the plane (at the light?)";
  }
  const double omega = 4.0 * std::asin(0.8);
  const double exact = 0.5 * 1.0 * omega;
  const double relError = v.relativeError;
  std::printf("VPLs: %zu, Σ Φ = %.5f W (relative error %.4f), closed form %.5f W\n",
              bake.vpls->size(), sum.g, relError, exact);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(v.totalFlux[c], sum[c], 1e-5 * sum[c]) << "channel " << c;
    EXPECT_NEAR(v.fluxPerBounce.at(0)[c], sum[c], 1e-5 * sum[c]);
    EXPECT_NEAR(sum[c], exact, 5.0 * relError * exact) << "channel " << c;
  }
  EXPECT_EQ(v.fluxPerBounce.size(), 1u) << "a lone plane reflects nothing onto itself";
  fs::remove_all(out);
}

// Dynamic instances are left out of the whole bake: content/cornell_box_dynamic is the Cornell
// box plus a dynamic sphere hanging 0.18 m over the floor, which would shadow the floor and the
// short block in the lightmap and catch VPLs if it were traced. Baked with the same settings
// and seed, its lightmap and VPLs must be bit-identical to the plain Cornell box's (its static
// instances come first, so the atlases agree), and the bake stays current when the sphere
// moves (sceneContentHash leaves dynamic transforms out).
TEST(VplBakeApp, DynamicInstancesAreLeftOutOfTheLightmapAndTheVpls) {
  const fs::path content = fs::path(BOUNCE_SOURCE_DIR) / "content";
  const auto bake = [](const fs::path& scene, const fs::path& out) {
    fs::remove_all(out);
    const std::string command = std::string(BOUNCE_BIN_DIR) + "/bounce-bake '" + scene.string() +
                                "' -o '" + out.string() +
                                "' --quiet --spp 16 --texel-budget 1024 --vpls 512 --seed 3";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  };
  const fs::path plainOut = fs::temp_directory_path() / "bounce_vpl_bake_app_plain.bake";
  const fs::path dynamicOut = fs::temp_directory_path() / "bounce_vpl_bake_app_dynamic.bake";
  const fs::path plainScene = content / "cornell_box/cornell_box.gltf";
  const fs::path dynamicScene = content / "cornell_box_dynamic/cornell_box_dynamic.gltf";
  bake(plainScene, plainOut);
  bake(dynamicScene, dynamicOut);
  const Bake plain = readBake(plainOut, loadScene(plainScene));
  Scene withSphere = loadScene(dynamicScene);
  ASSERT_EQ(withSphere.instances.back().name, "sphere");
  ASSERT_EQ(withSphere.instances.back().mobility, Mobility::Dynamic);
  withSphere.instances.back().transform[3] = glm::vec4(0.1f, 0.3f, 0.4f, 1.0f);
  const Bake dynamic = readBake(dynamicOut, withSphere);  // current wherever the sphere is
  EXPECT_EQ(dynamic.layout.find(static_cast<uint32_t>(withSphere.instances.size() - 1)), nullptr);
  ASSERT_EQ(plain.irradiance.width, dynamic.irradiance.width);
  ASSERT_EQ(plain.irradiance.height, dynamic.irradiance.height);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < plain.irradiance.pixels.size(); ++i)
    differing += plain.irradiance.pixels[i] != dynamic.irradiance.pixels[i] ? 1 : 0;
  EXPECT_EQ(differing, 0u) << "lightmap texels changed by the dynamic sphere";
  ASSERT_TRUE(plain.vpls && dynamic.vpls);
  ASSERT_EQ(plain.vpls->size(), dynamic.vpls->size());
  for (std::size_t i = 0; i < plain.vpls->size(); ++i) {
    EXPECT_EQ((*plain.vpls)[i].position, (*dynamic.vpls)[i].position) << "VPL " << i;
    EXPECT_EQ((*plain.vpls)[i].flux, (*dynamic.vpls)[i].flux) << "VPL " << i;
  }
  fs::remove_all(plainOut);
  fs::remove_all(dynamicOut);
}

}  // namespace
}  // namespace bounce
