// Camera and light nodes under scaled, sheared and mirrored transforms: the camera keeps a
// rigid frame (so the view matrix never rescales znear..zfar) and light directions stay unit.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "expect_load_error.h"
#include "gltf_fixture.h"
#include "scene/load.h"

namespace bounce {
namespace {

const double kHalf = std::sqrt(0.5);

// The triangle fixture plus a perspective camera 3 m up looking down −y (quaternion −90° about
// x), as in content/point_over_plane; `scale` goes on the camera node itself.
test::GltfFixture cameraAbove(const nlohmann::json& scale) {
  test::GltfFixture f = test::GltfFixture::triangle();
  f.doc["cameras"] = {{{"name", "eye"},
                       {"type", "perspective"},
                       {"perspective", {{"yfov", 1.0}, {"znear", 0.1}, {"zfar", 100.0}}}}};
  nlohmann::json camera = {{"name", "camera"},
                           {"camera", 0},
                           {"rotation", {-kHalf, 0.0, 0.0, kHalf}},
                           {"translation", {0.0, 3.0, 0.0}}};
  if (!scale.is_null()) camera["scale"] = scale;
  f.doc["nodes"].push_back(camera);
  f.doc["scenes"][0]["nodes"] = {0, 1};
  return f;
}

void expectRigid(const glm::mat4& m) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(glm::length(glm::vec3(m[c])), 1.0f, 1e-6f) << "column " << c;
    for (int d = c + 1; d < 3; ++d)
      EXPECT_NEAR(glm::dot(glm::vec3(m[c]), glm::vec3(m[d])), 0.0f, 1e-6f) << c << "·" << d;
  }
  // Right-handed: X × Y = Z (determinant +1).
  EXPECT_NEAR(glm::dot(glm::cross(glm::vec3(m[0]), glm::vec3(m[1])), glm::vec3(m[2])), 1.0f, 1e-6f);
}

TEST(GltfCamera, ScaleOnTheCameraNodeIsStripped) {
  test::TempDir dir;
  cameraAbove(nullptr).writeGltf(dir / "plain.gltf");
  const Camera plain = loadScene(dir / "plain.gltf").cameras.at(0);
  for (const nlohmann::json& scale :
       {nlohmann::json{0.01, 0.01, 0.01}, nlohmann::json{3.0, 0.5, 20.0}}) {
    cameraAbove(scale).writeGltf(dir / "scaled.gltf");
    const Camera scaled = loadScene(dir / "scaled.gltf").cameras.at(0);
    expectRigid(scaled.cameraToWorld);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        EXPECT_NEAR(scaled.cameraToWorld[c][r], plain.cameraToWorld[c][r], 1e-6f)
            << "scale " << scale.dump() << " [" << c << "][" << r << "]";
  }
}

// A non-uniformly scaled, rotated parent shears the camera: the loaded frame keeps the view
// direction, makes up orthogonal to it, and is a rotation even when the parent mirrors.
TEST(GltfCamera, ShearedAndMirroredParentsGiveARotation) {
  test::TempDir dir;
  for (const nlohmann::json& scale : {nlohmann::json{1.0, 5.0, 0.2}, nlohmann::json{-1.0, 1.0, 1.0},
                                      nlohmann::json{2.0, 2.0, -2.0}}) {
    test::GltfFixture f = cameraAbove(nullptr);
    f.doc["nodes"].push_back({{"name", "parent"},
                              {"rotation", {0.0, 0.0, 0.38268343236, 0.92387953251}},  // 45° z
                              {"scale", scale},
                              {"children", {1}}});
    f.doc["scenes"][0]["nodes"] = {0, 2};
    f.writeGltf(dir / "sheared.gltf");
    const Camera camera = loadScene(dir / "sheared.gltf").cameras.at(0);
    expectRigid(camera.cameraToWorld);
    // The view direction is the parent's linear part applied to the node's −Z (world −y before
    // the parent): P·(0,−1,0), normalized.
    const glm::mat4 rot = glm::mat4_cast(glm::quat(0.92387953251f, 0, 0, 0.38268343236f));
    const glm::vec3 s(scale[0].get<float>(), scale[1].get<float>(), scale[2].get<float>());
    const glm::vec3 expected =
        glm::normalize(glm::vec3(rot * glm::vec4(s * glm::vec3(0, -1, 0), 0)));
    EXPECT_LT(glm::distance(camera.forward(), expected), 1e-6f) << scale.dump();
  }
}

TEST(GltfCamera, ZeroScaleIsALoadErrorNamingTheCamera) {
  test::TempDir dir;
  cameraAbove({0.0, 1.0, 1.0}).writeGltf(dir / "flat.gltf");
  test::expectLoadError(dir / "flat.gltf", "'eye'");
}

// A spot light under a scaled, mirrored parent still travels along a unit direction: the
// parent's linear part applied to −Z, normalized.
TEST(GltfLight, DirectionIsUnitUnderScaledMirroredParents) {
  test::TempDir dir;
  for (const nlohmann::json& scale :
       {nlohmann::json{0.01, 0.01, 0.01}, nlohmann::json{1.0, 1.0, -0.01},
        nlohmann::json{-3.0, 0.5, 7.0}}) {
    test::GltfFixture f = test::GltfFixture::triangle();
    f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    f.doc["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights",
           {{{"type", "spot"}, {"intensity", 683.0}, {"spot", {{"outerConeAngle", 0.5}}}}}}}}};
    f.doc["nodes"].push_back({{"name", "parent"},
                              {"rotation", {0.0, 0.38268343236, 0.0, 0.92387953251}},  // 45° y
                              {"scale", scale},
                              {"children", {2}}});
    f.doc["nodes"].push_back({{"name", "spot"},
                              {"rotation", {-kHalf, 0.0, 0.0, kHalf}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    f.doc["scenes"][0]["nodes"] = {0, 1};
    f.writeGltf(dir / "light.gltf");
    const Light light = loadScene(dir / "light.gltf").lights.at(0);
    EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-6f) << scale.dump();
    // The spot node turns −Z to −Y; the parent scales y by scale[1] (> 0) then rotates about y,
    // which leaves ±y alone: the light still travels straight down.
    EXPECT_LT(glm::distance(light.direction, glm::vec3(0, -1, 0)), 1e-6f) << scale.dump();
  }
}

// glTF's absent zfar means an infinite far plane; the finite stand-in must stay beyond znear
// even for a far znear (a projection with znear >= zfar clips everything).
TEST(GltfCamera, AbsentZfarStaysBeyondZnear) {
  test::TempDir dir;
  for (const double znear : {0.1, 2000.0}) {
    test::GltfFixture f = cameraAbove(nullptr);
    f.doc["cameras"][0]["perspective"] = {{"yfov", 1.0}, {"znear", znear}};
    f.writeGltf(dir / "nofar.gltf");
    const Camera camera = loadScene(dir / "nofar.gltf").cameras.at(0);
    EXPECT_FLOAT_EQ(camera.znear, static_cast<float>(znear));
    EXPECT_GE(camera.zfar, 1000.0f);
    EXPECT_GE(camera.zfar, 2.0f * camera.znear) << "znear " << znear;
  }
}

}  // namespace
}  // namespace bounce
