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
