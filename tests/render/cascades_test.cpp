// GL-free: the cascade split, fit and snap of engine/render/cascades.h against its invariants.
#include "render/cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

Camera lookAt(glm::vec3 eye, glm::vec3 target, float yfov = 0.9f) {
  Camera camera;
  camera.yfov = yfov;
  camera.znear = 0.05f;
  camera.zfar = 1000.0f;
  camera.cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  return camera;
}

// A 200 m × 200 m ground with 10 m of height above it: what the cascades must cover.
Bounds groundBounds() {
  return Bounds{{-100, 0, -100}, {100, 10, 100}, false};
}

glm::vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  return glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
}

TEST(CascadeSplits, EndsExactIncreasingAndBetweenUniformAndLogarithmic) {
  const float n = 0.1f, f = 200.0f;
  for (const int count : {1, 2, 3, 4}) {
    const std::vector<float> uniform = cascadeSplits(n, f, count, 0.0f);
    const std::vector<float> logarithmic = cascadeSplits(n, f, count, 1.0f);
    const std::vector<float> practical = cascadeSplits(n, f, count, 0.75f);
    ASSERT_EQ(practical.size(), static_cast<std::size_t>(count) + 1);
    EXPECT_EQ(practical.front(), n);
    EXPECT_EQ(practical.back(), f);
    for (int i = 1; i < count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      EXPECT_NEAR(uniform[k], n + (f - n) * i / count, 1e-4f);
      EXPECT_NEAR(logarithmic[k], n * std::pow(f / n, static_cast<float>(i) / count), 1e-4f);
      EXPECT_GT(practical[k], practical[k - 1]);
      EXPECT_GE(practical[k], logarithmic[k]);
      EXPECT_LE(practical[k], uniform[k]);
    }
  }
}

// Every corner of each cascade's frustum slice (blend band included) lies inside its
// orthographic box, seen through the float matrix the shadow pass draws with.
TEST(CascadeFit, EachBoxContainsItsFrustumSlice) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::vec3 eye(unit(rng) * 100 - 50, 1 + unit(rng) * 20, unit(rng) * 100 - 50);
    const glm::vec3 target = eye + randomUnit(rng);
    if (std::abs(glm::normalize(target - eye).y) > 0.99f) continue;  // lookAt needs a horizon
    const Camera camera = lookAt(eye, target, 0.3f + unit(rng) * 1.5f);
    const float aspect = 0.5f + unit(rng) * 2.0f;
    glm::vec3 light = randomUnit(rng);
    if (light.y > 0.0f) light.y = -light.y;
    CascadeSettings settings;
    settings.count = 1 + trial % kMaxCascades;
    settings.resolution = 512 << (trial % 4);
    const std::vector<Cascade> cascades =
        fitCascades(camera, aspect, light, Bounds{}, settings);  // depth from the slice alone
    ASSERT_EQ(cascades.size(), static_cast<std::size_t>(settings.count));
    for (std::size_t i = 0; i < cascades.size(); ++i) {
      const Cascade& c = cascades[i];
      ASSERT_LT(c.nearDepth, c.splitDepth);
      for (const glm::dvec3& corner :
           frustumSliceCorners(camera, aspect, c.nearDepth, c.splitDepth)) {
        const glm::vec4 clip = c.worldToClip * glm::vec4(glm::vec3(corner), 1.0f);
        for (int axis = 0; axis < 3; ++axis)
          EXPECT_LE(std::abs(clip[axis]), 1.0f + 1e-5f)
              << "trial " << trial << " cascade " << i << " axis " << axis;
      }
    }
  }
}

// With scene bounds, the depth range is the bounds' own along the light (plus a texel), the same
// for every camera: casters between the light and the slice are in the map.
TEST(CascadeFit, DepthRangeIsTheScenesWholeDepthAlongTheLight) {
  const glm::vec3 light = glm::normalize(glm::vec3(0.3f, -1, 0.2f));
  const Bounds bounds = groundBounds();
  double lo = 1e30, hi = -1e30;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner((k & 1) ? bounds.hi.x : bounds.lo.x,
                            (k & 2) ? bounds.hi.y : bounds.lo.y,
                            (k & 4) ? bounds.hi.z : bounds.lo.z);
    lo = std::min(lo, glm::dot(corner, glm::dvec3(light)));
    hi = std::max(hi, glm::dot(corner, glm::dvec3(light)));
  }
  for (const glm::vec3 eye : {glm::vec3(0, 2, 0), glm::vec3(40, 5, -30)}) {
    for (const Cascade& c :
         fitCascades(lookAt(eye, eye + glm::vec3(1, -0.2f, 0)), 1.5f, light, bounds, {})) {
      EXPECT_NEAR(c.depthNear, lo - c.texelSize, 1e-6 * std::abs(lo) + 1e-9);
      EXPECT_NEAR(c.depthFar, hi + c.texelSize, 1e-6 * std::abs(hi) + 1e-9);
    }
  }
}

// The blend band at the far end of cascade i lies inside cascade i+1's slice, so the shader's
// cross-fade reads two maps that both cover the fragment; the last cascade has no band.
TEST(CascadeFit, BlendBandsLieInBothCascades) {
  const Camera camera = lookAt({0, 2, 0}, {0, 1.5f, -10});
  const std::vector<Cascade> cascades =
      fitCascades(camera, 16.0f / 9.0f, glm::vec3(0.3f, -1, 0.2f), groundBounds(), {});
  ASSERT_EQ(cascades.size(), 4u);
  for (std::size_t i = 0; i + 1 < cascades.size(); ++i) {
    EXPECT_LT(cascades[i].blendStart, cascades[i].splitDepth);
    EXPECT_LE(cascades[i + 1].nearDepth, cascades[i].blendStart + 1e-4f);
    EXPECT_EQ(cascades[i + 1].nearDepth < cascades[i].splitDepth, true);
  }
  EXPECT_EQ(cascades.back().blendStart, cascades.back().splitDepth);
}

// Snapping: each box's lower corner is a whole number of texels from the light-space origin,
// and the box's side is the same whatever the camera's orientation.
TEST(CascadeSnap, BoxCornerIsWholeTexelsAndSideIgnoresCameraPose) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const glm::vec3 light = glm::normalize(glm::vec3(0.4f, -1.0f, 0.25f));
  std::vector<double> sides;
  for (int trial = 0; trial < 50; ++trial) {
    const glm::vec3 eye(unit(rng) * 100 - 50, 2 + unit(rng) * 5, unit(rng) * 100 - 50);
    const float yaw = unit(rng) * 6.28f, pitch = -0.6f * unit(rng);
    const glm::vec3 dir(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                        std::cos(pitch) * std::cos(yaw));
    Camera camera = lookAt(eye, eye + dir);
    camera.zfar = 80.0f;  // inside the ground's bounds whatever the pose: same covered range
    const std::vector<Cascade> cascades = fitCascades(camera, 1.5f, light, Bounds{}, {});
    for (std::size_t i = 0; i < cascades.size(); ++i) {
      const Cascade& c = cascades[i];
      for (int axis = 0; axis < 2; ++axis) {
        const double texels = c.boxMin[axis] / c.texelSize;
        EXPECT_NEAR(texels, std::round(texels), 1e-6) << "cascade " << i;
      }
      if (trial == 0) sides.push_back(c.boxSide);
      EXPECT_EQ(c.boxSide, sides[i]) << "cascade " << i << " trial " << trial;
    }
  }
}

// The texel a fixed world point falls in, as a fractional texel coordinate through the float
// matrix the GPU uses.
glm::dvec2 texelCoordinate(const Cascade& c, glm::vec3 world, int resolution) {
  const glm::vec4 clip = c.worldToClip * glm::vec4(world, 1.0f);
  return (glm::dvec2(clip.x, clip.y) * 0.5 + 0.5) * static_cast<double>(resolution);
}

// A camera moved by less than a texel: the box moves by 0 or 1 whole texel per axis, the same
// world points keep their position inside their texel (so the map's contents only shift), and a
// move that keeps the slice's centre in its texel leaves the box where it was.
TEST(CascadeSnap, SubTexelCameraMoveShiftsTheMapByWholeTexelsOrNotAtAll) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const glm::vec3 light = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.5f));
  CascadeSettings settings;
  settings.resolution = 1024;
  int unchanged = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const glm::vec3 eye(unit(rng) * 20 - 10, 1.7f, unit(rng) * 20 - 10);
    const Camera before =
        lookAt(eye, eye + glm::vec3(std::sin(trial * 1.0f), -0.3f, std::cos(trial * 1.0f)));
    const std::vector<Cascade> a = fitCascades(before, 1.5f, light, groundBounds(), settings);
    for (std::size_t i = 0; i < a.size(); ++i) {
      // Move the camera by a random vector shorter than this cascade's texel.
      Camera after = before;
      const glm::vec3 step = randomUnit(rng) * static_cast<float>(a[i].texelSize * 0.9 * unit(rng));
      after.cameraToWorld[3] += glm::vec4(step, 0.0f);
      const std::vector<Cascade> b = fitCascades(after, 1.5f, light, groundBounds(), settings);
      ASSERT_EQ(a[i].boxSide, b[i].boxSide);
      const glm::dvec2 shift = (b[i].boxMin - a[i].boxMin) / a[i].texelSize;
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_NEAR(shift[axis], std::round(shift[axis]), 1e-6);
        EXPECT_LE(std::abs(std::round(shift[axis])), 1.0);
      }
      if (shift == glm::dvec2(0.0)) ++unchanged;
      // A world point near the slice keeps its sub-texel position.
      const glm::vec3 world = before.position() + before.forward() * (0.5f * a[i].splitDepth);
      const glm::dvec2 ta = texelCoordinate(a[i], world, settings.resolution);
      const glm::dvec2 tb = texelCoordinate(b[i], world, settings.resolution);
      const glm::dvec2 moved = tb - ta + shift;  // the box's shift undone
      EXPECT_NEAR(moved.x, 0.0, 2e-3) << "cascade " << i;
      EXPECT_NEAR(moved.y, 0.0, 2e-3) << "cascade " << i;
    }
  }
  EXPECT_GT(unchanged, 0);
}

// A camera whose slice centre sits in the middle of a texel, moved by under half a texel in any
// direction: the same snapped box, bit for bit.
TEST(CascadeSnap, MoveWithinTheTexelGivesTheSameSnappedOrigin) {
  const glm::vec3 light = glm::normalize(glm::vec3(0.2f, -1.0f, -0.4f));
  const glm::dmat3 rotation = lightRotation(light);
  const glm::dmat3 toWorld = glm::transpose(rotation);
  CascadeSettings settings;
  settings.resolution = 2048;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    Camera camera = lookAt({3 + trial * 0.37f, 1.7f, 4}, {3.5f, 1.2f - 0.05f * trial, -4});
    for (std::size_t i = 0; i < static_cast<std::size_t>(settings.count); ++i) {
      // The box corner is floor((c − r)/t)·t: the fractional part of (c − r)/t is where the
      // slice centre sits in its cell. Move the camera across the light so that it is ½, ½.
      const Cascade c = fitCascades(camera, 1.5f, light, groundBounds(), settings)[i];
      const glm::dvec2 cell = (glm::dvec2(rotation * c.centre) - c.radius) / c.texelSize;
      const glm::dvec2 toMiddle = (0.5 - (cell - glm::floor(cell))) * c.texelSize;
      Camera centred = camera;
      centred.cameraToWorld[3] += glm::vec4(glm::vec3(toWorld * glm::dvec3(toMiddle, 0.0)), 0.0f);
      const Cascade reference = fitCascades(centred, 1.5f, light, groundBounds(), settings)[i];
      const glm::dvec2 check =
          (glm::dvec2(rotation * reference.centre) - reference.radius) / reference.texelSize;
      ASSERT_NEAR(check.x - std::floor(check.x), 0.5, 1e-3);
      ASSERT_NEAR(check.y - std::floor(check.y), 0.5, 1e-3);
      for (int move = 0; move < 10; ++move) {
        Camera moved = centred;
        const glm::vec3 step = randomUnit(rng) * static_cast<float>(c.texelSize * 0.45 * unit(rng));
        moved.cameraToWorld[3] += glm::vec4(step, 0.0f);
        const Cascade after = fitCascades(moved, 1.5f, light, groundBounds(), settings)[i];
        EXPECT_EQ(after.boxMin, reference.boxMin) << "cascade " << i << " trial " << trial;
        EXPECT_EQ(after.worldToClip, reference.worldToClip);
      }
    }
  }
}

}  // namespace
}  // namespace bounce
