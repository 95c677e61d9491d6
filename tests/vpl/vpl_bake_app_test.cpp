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

#include <nlohmann/json.hpp>

#include "bake/bake_folder.h"
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
  const nlohmann::json manifest = nlohmann::json::parse(bake.manifestJson);
  const nlohmann::json& v = manifest.at("vpls");
  EXPECT_EQ(v.at("count").get<std::size_t>(), bake.vpls->size());
  EXPECT_LE(bake.vpls->size(), 3000u);
  glm::dvec3 sum(0.0);
  for (const Vpl& vpl : *bake.vpls) {
    sum += glm::dvec3(vpl.flux);
    EXPECT_NEAR(vpl.position.y, 0.0f, 1e-5f) << "a VPL off the plane (at the light?)";
  }
  const double omega = 4.0 * std::asin(0.8);
  const double exact = 0.5 * 1.0 * omega;
  const double relError = v.at("relativeError").get<double>();
  std::printf("VPLs: %zu, Σ Φ = %.5f W (relative error %.4f), closed form %.5f W\n",
              bake.vpls->size(), sum.g, relError, exact);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(v.at("totalFlux")[c].get<double>(), sum[c], 1e-5 * sum[c]) << "channel " << c;
    EXPECT_NEAR(v.at("fluxPerBounce")[0][c].get<double>(), sum[c], 1e-5 * sum[c]);
    EXPECT_NEAR(sum[c], exact, 5.0 * relError * exact) << "channel " << c;
  }
  EXPECT_EQ(v.at("fluxPerBounce").size(), 1u) << "a lone plane reflects nothing onto itself";
  fs::remove_all(out);
}

}  // namespace
}  // namespace bounce
