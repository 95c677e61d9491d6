// shaders/tonemap.glsl mirrors bounce::toneMap: the viewer's display pass, run into a float
// target, gives the CPU's values. GPU float exp2/pow are accurate to a few ulp; 1e-4 is far below
// one 8-bit step (1/255 ≈ 4e-3) yet far above rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gl/render_target.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "image/tonemap.h"
#include "render/tonemap_pass.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

TEST(TonemapShader, MatchesCpuToneMap) {
  testContext();
  constexpr int kWidth = 64;
  std::vector<glm::vec3> radiance(kWidth);
  for (int i = 0; i < kWidth; ++i) {
    const float x = 1e-4f * std::pow(1.25f, static_cast<float>(i));  // 1e-4 … ~1.3e2
    radiance[static_cast<std::size_t>(i)] = {x, 0.5f * x, 3.0f * x};
  }
  const gl::Texture2D input(kWidth, 1, radiance, gl::Filter::Nearest);
  gl::RenderTarget target(kWidth, 1);
  TonemapPass pass(gl::shaderDirectory());
  for (const float ev : {0.0f, -1.5f, 2.0f}) {
    target.bind();
    pass.draw(input, ev);
    const Image out = target.read();
    for (int i = 0; i < kWidth; ++i) {
      const glm::vec3 expected = toneMap(radiance[static_cast<std::size_t>(i)], ev);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out.at(i, 0)[c], expected[c], 1e-4f) << "texel " << i << " EV " << ev;
    }
  }
}

}  // namespace
}  // namespace bounce::test

namespace bounce::test {
namespace {

// The viewer's cost view (shaders/cost_colour.glsl) draws what bounce-render's PNG holds
// (render/cost_view.h, costFalseColour): the ramp over each count and the legend bar with its
// ticks, for each of the three counts. Counts 0 … 2.5 × scaleMax cover every ramp segment and
// the white beyond; 64 × 64 gives a 4-row bar.
TEST(TonemapShader, CostViewMatchesTheCpuFalseColourAndLegend) {
  testContext();
  constexpr int kSize = 64;
  const float scaleMax = 50.0f;
  Image counts(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float c = static_cast<float>(x + kSize * y) * 2.5f * scaleMax / (kSize * kSize);
      counts.at(x, y) = {c, 2.0f * c, 0.5f * c};
    }
  // Texture rows go bottom-up (GL), the image's top-down.
  std::vector<glm::vec3> texels;
  for (int y = kSize - 1; y >= 0; --y)
    for (int x = 0; x < kSize; ++x) texels.push_back(counts.at(x, y));
  const gl::Texture2D input(kSize, kSize, texels, gl::Filter::Nearest);
  gl::RenderTarget target(kSize, kSize);
  TonemapPass pass(gl::shaderDirectory());
  for (const CostCount count : {CostCount::Lights, CostCount::Vpls, CostCount::ShadowTaps}) {
    target.bind();
    pass.draw(input, 0.0f, TonemapPass::CostDisplay{count, scaleMax});
    const Image out = target.read();
    const Image expected = costFalseColour(counts, count, scaleMax);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(out.at(x, y)[c], expected.at(x, y)[c], 1e-5f)
              << "pixel (" << x << ", " << y << ") count " << costCountName(count);
  }
}

}  // namespace
}  // namespace bounce::test
