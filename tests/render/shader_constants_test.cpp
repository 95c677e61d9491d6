// The renderer's shaders get the constants they share with the C++ from the C++ at load
// (render/shader_constants.h): no shader file declares one, and the values that reach a
// compiled shader are the C++ ones.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "gl/draw_state.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "image/luminance.h"
#include "render/cascades.h"
#include "render/shader_constants.h"
#include "render/view_mode_colours.h"
#include "scene/scene.h"
#include "support/test_context.h"

namespace bounce::test {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ShaderConstants, NoShaderFileDeclaresThem) {
  const fs::path shaders = fs::path(BOUNCE_SOURCE_DIR) / "shaders";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(shaders)) {
    ++files;
    const std::string text = readText(entry.path());
    for (const gl::ShaderDefine& d : shaderConstants()) {
      const std::regex declared("(const\\s+\\w+(\\s*\\[\\w*\\])?\\s+" + d.name +
                                "\\b)|(#\\s*define\\s+" + d.name + "\\b)");
      EXPECT_FALSE(std::regex_search(text, declared))
          << entry.path() << " declares " << d.name << ", which the C++ hands every shader";
    }
  }
  EXPECT_GT(files, 20);
}

// One pixel per value, drawn by a shader that reads only the defines.
TEST(ShaderConstants, TheCompiledShaderSeesTheCppValues) {
  testContext();
  const fs::path dir = fs::temp_directory_path() /
                       ("bounce_shader_constants_" +
                        std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  const fs::path fragment = dir / "values.frag";
  std::ofstream(fragment)
      << "#version 330 core\n"
         "out vec4 color;\n"
         "void main() {\n"
         "  int x = int(gl_FragCoord.x);\n"
         "  if (x == 0) color = vec4(PI, float(LIGHT_SPOT), float(LIGHTING_VPL), 1.0);\n"
         "  else if (x == 1) color = vec4(LUMINANCE_WEIGHTS, 1.0);\n"
         "  else color = vec4(CASCADE_COLOURS[3], 1.0);\n"
         "}\n";
  gl::Program program(gl::shaderDirectory() / "fullscreen.vert", fragment, shaderConstants());
  gl::RenderTarget target(3, 1);
  target.bind();
  gl::clear(glm::vec4(0.0f));
  program.use();
  gl::drawFullscreenTriangle();
  const Image image = target.read();
  fs::remove_all(dir);

  EXPECT_EQ(image.at(0, 0).r, std::numbers::pi_v<float>);
  EXPECT_EQ(image.at(0, 0).g, static_cast<float>(static_cast<int>(LightType::Spot)));
  EXPECT_EQ(image.at(0, 0).b, static_cast<float>(static_cast<int>(ShaderLighting::Vpl)));
  EXPECT_EQ(image.at(1, 0).r, static_cast<float>(kLuminanceR));
  EXPECT_EQ(image.at(1, 0).g, static_cast<float>(kLuminanceG));
  EXPECT_EQ(image.at(1, 0).b, static_cast<float>(kLuminanceB));
  EXPECT_EQ(image.at(2, 0).r, cascadeColour(3).r);
  EXPECT_EQ(image.at(2, 0).g, cascadeColour(3).g);
  EXPECT_EQ(image.at(2, 0).b, cascadeColour(3).b);
}

}  // namespace
}  // namespace bounce::test
