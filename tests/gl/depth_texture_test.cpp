// Depth textures and depth-only passes: what a depth pass writes, a comparison sampler reads
// back as ref ≤ depth (1 = lit), for 2D maps (border: lit) and each cube face.
#include <gtest/gtest.h>

#include "gl/depth_texture.h"
#include "gl/draw_state.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "gl_test_support.h"

namespace bounce::gl::test {
namespace {

// Writes depth uDepth everywhere (a fullscreen triangle).
const char* kWriteDepth =
    "#version 330 core\n"
    "uniform float uDepth;\n"
    "void main() { gl_FragDepth = uDepth; }\n";

TEST(DepthTexture, ComparisonSamplerReadsWhatADepthPassWrote) {
  testContext();
  const ScratchDir dir("depth2d");
  Program write(shaderDirectory() / "fullscreen.vert", dir.write("write.frag", kWriteDepth));
  const auto read = dir.write("read.frag",
                              "#version 330 core\n"
                              "uniform sampler2DShadow uMap;\n"
                              "in vec2 vUv;\n"
                              "out vec4 color;\n"
                              "void main() {\n"
                              "  color = vec4(texture(uMap, vec3(vUv, 0.4)),\n"
                              "               texture(uMap, vec3(vUv, 0.6)),\n"
                              "               texture(uMap, vec3(vUv + 2.0, 0.9)), 1.0);\n"
                              "}\n");
  Program compare(shaderDirectory() / "fullscreen.vert", read);
  DepthTexture2D map(8, 8);
  DepthTarget target;
  target.bind(map);
  clearDepth();
  setDepthTest(true);
  write.set("uDepth", 0.5f);
  drawFullscreenTriangle();
  checkErrors("depth pass");

  RenderTarget out(4, 4);
  out.bind();
  clear(glm::vec4(0.0f));
  setDepthTest(false);
  map.bind(0);
  compare.set("uMap", 0);
  drawFullscreenTriangle();
  const Image image = out.read();
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(image.at(x, y).r, 1.0f);  // 0.4 ≤ 0.5: lit
      EXPECT_EQ(image.at(x, y).g, 0.0f);  // 0.6 > 0.5: shadowed
      EXPECT_EQ(image.at(x, y).b, 1.0f);  // outside the map: border depth 1, lit
    }
}

TEST(DepthTexture, EachCubeFaceHoldsItsOwnDepth) {
  testContext();
  const ScratchDir dir("depthcube");
  Program write(shaderDirectory() / "fullscreen.vert", dir.write("write.frag", kWriteDepth));
  // Face f gets depth (f + 1)/10; looking along each face's axis must find it.
  DepthCubeMap cube(4);
  DepthTarget target;
  setDepthTest(true);
  for (int face = 0; face < 6; ++face) {
    target.bind(cube, face);
    clearDepth();
    write.set("uDepth", (face + 1) / 10.0f);
    drawFullscreenTriangle();
  }
  const auto read = dir.write("read.frag",
                              "#version 330 core\n"
                              "uniform samplerCubeShadow uCube;\n"
                              "uniform vec3 uDirection;\n"
                              "uniform float uReference;\n"
                              "out vec4 color;\n"
                              "void main() {\n"
                              "  color = vec4(texture(uCube, vec4(uDirection, uReference)));\n"
                              "}\n");
  Program compare(shaderDirectory() / "fullscreen.vert", read);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  RenderTarget out(1, 1);
  setDepthTest(false);
  cube.bind(0);
  compare.set("uCube", 0);
  for (int face = 0; face < 6; ++face) {
    compare.set("uDirection", axes[face]);
    for (const float offset : {-0.05f, 0.05f}) {
      out.bind();
      clear(glm::vec4(0.5f));
      compare.set("uReference", (face + 1) / 10.0f + offset);
      drawFullscreenTriangle();
      EXPECT_EQ(out.read().at(0, 0).r, offset < 0.0f ? 1.0f : 0.0f)
          << "face " << face << " reference offset " << offset;
    }
  }
  checkErrors("cube comparison");
}

TEST(DepthTexture, RejectsImpossibleSizesAndFaces) {
  testContext();
  EXPECT_THROW(DepthTexture2D(0, 4), std::invalid_argument);
  EXPECT_THROW(DepthCubeMap(-1), std::invalid_argument);
  DepthCubeMap cube(2);
  DepthTarget target;
  EXPECT_THROW(target.bind(cube, 6), std::invalid_argument);
}

}  // namespace
}  // namespace bounce::gl::test
