// Shaders are files; every failure names the file (and, for compile errors, the line) so a
// broken shader is found without reading driver logs by hand.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <string>

#include "gl/draw_state.h"
#include "gl/render_target.h"
#include "gl/shader.h"
#include "gl_test_support.h"

namespace bounce::gl::test {
namespace {

std::string buildError(const std::filesystem::path& vertex, const std::filesystem::path& fragment) {
  try {
    Program program(vertex, fragment);
  } catch (const ShaderError& e) {
    return e.what();
  }
  return "";
}

const char* kVertex = R"(#version 330 core
void main() { gl_Position = vec4(0.0); }
)";

TEST(Shader, SyntaxErrorNamesFileAndLine) {
  testContext();
  const ScratchDir dir("syntax");
  const auto vertex = dir.write("ok.vert", kVertex);
  const auto fragment = dir.write("broken.frag",
                                  "#version 330 core\n"
                                  "out vec4 color;\n"
                                  "void main() {\n"
                                  "  color = vec4(1.0)\n"  // line 4: missing ';'
                                  "}\n");
  const std::string error = buildError(vertex, fragment);
  ASSERT_FALSE(error.empty());
  // The statement ends at line 5's '}', where the parser notices; either line is the culprit.
  EXPECT_TRUE(std::regex_search(error, std::regex(fragment.string() + ":[45]:"))) << error;
}

TEST(Shader, ErrorInIncludedFileNamesThatFileAndItsLine) {
  testContext();
  const ScratchDir dir("include");
  const auto vertex = dir.write("ok.vert", kVertex);
  const auto included = dir.write("helpers.glsl",
                                  "// helpers\n"
                                  "float halve(float x) { return 0.5 * x; }\n"
                                  "float broken(float x) { return x * undefinedName; }\n");
  const auto fragment = dir.write("main.frag",
                                  "#version 330 core\n"
                                  "#include \"helpers.glsl\"\n"
                                  "out vec4 color;\n"
                                  "void main() {\n"
                                  "  color = vec4(halve(1.0)) + undeclaredToo;\n"  // line 5
                                  "}\n");
  const std::string error = buildError(vertex, fragment);
  EXPECT_NE(error.find(included.string() + ":3:"), std::string::npos) << error;
  EXPECT_NE(error.find(fragment.string() + ":5:"), std::string::npos) << error;
}

// The C++'s constants go right after #version, in every stage; a compile error after them is
// still reported at its own line of its own file.
TEST(Shader, DefinesFollowTheVersionLineAndKeepLineNumbers) {
  testContext();
  const ScratchDir dir("defines");
  const auto included = dir.write("uses.glsl", "float twice() { return 2.0 * HALF; }\n");
  const auto fragment =
      dir.write("main.frag",
                "#version 330 core\n"
                "#include \"uses.glsl\"\n"
                "out vec4 color;\n"
                "void main() { color = vec4(twice(), float(COUNT), 0.0, 1.0); }\n");
  const ShaderDefines defines = {{"HALF", "0.5"}, {"COUNT", "3"}};
  const ShaderSource source = readShaderSource(fragment, defines);
  EXPECT_EQ(
      source.text.rfind("#version 330 core\n#define HALF 0.5\n#define COUNT 3\n#line 2 0\n", 0), 0u)
      << source.text;
  EXPECT_EQ(source.text.find("#define", source.text.find("#line 1 1")), std::string::npos)
      << "an included file got the defines again:\n"
      << source.text;
  const auto vertex = dir.write("ok.vert", kVertex);
  EXPECT_NO_THROW(Program(vertex, fragment, defines)) << "the defines did not reach the compiler";
  // Without them the names are undeclared, reported at their own file and line.
  const std::string error = buildError(vertex, fragment);
  EXPECT_NE(error.find(included.string() + ":1:"), std::string::npos) << error;
  const auto broken = dir.write("broken.frag",
                                "#version 330 core\n"
                                "out vec4 color;\n"
                                "void main() { color = vec4(HALF) + undeclared; }\n");  // line 3
  std::string brokenError;
  try {
    Program program(vertex, broken, defines);
  } catch (const ShaderError& e) {
    brokenError = e.what();
  }
  EXPECT_NE(brokenError.find(broken.string() + ":3:"), std::string::npos) << brokenError;
}

TEST(Shader, MissingFileNamesThePath) {
  testContext();
  const ScratchDir dir("missing");
  const auto vertex = dir.write("ok.vert", kVertex);
  const std::string error = buildError(vertex, dir.path() / "absent.frag");
  EXPECT_NE(error.find((dir.path() / "absent.frag").string()), std::string::npos) << error;
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
}

TEST(Shader, MissingIncludeNamesItAndTheIncludingLine) {
  const ScratchDir dir("missing-include");
  const auto fragment = dir.write("main.frag", "#version 330 core\n\n#include \"gone.glsl\"\n");
  try {
    readShaderSource(fragment);
    FAIL() << "no error";
  } catch (const ShaderError& e) {
    const std::string error = e.what();
    EXPECT_NE(error.find(fragment.string() + ":3: "), std::string::npos) << error;
    EXPECT_NE(error.find((dir.path() / "gone.glsl").string()), std::string::npos) << error;
  }
}

TEST(Shader, LogAttributionReadsMesaAndNvidiaFormats) {
  const std::vector<std::filesystem::path> files = {"a.frag", "b.glsl"};
  EXPECT_EQ(attributeLog("1:7(12): error: `x' undeclared\n", files),
            "b.glsl:7:12: error: `x' undeclared\n");
  EXPECT_EQ(attributeLog("0(3) : error C1008: undefined variable\n", files),
            "a.frag:3: error C1008: undefined variable\n");
  EXPECT_EQ(attributeLog("warning without place\n", files), "warning without place\n");
}

TEST(ShaderDirectory, EnvironmentOverridesAndBadValueIsNamed) {
  const ScratchDir dir("shader-dir");
  ::setenv("BOUNCE_SHADER_DIR", dir.path().c_str(), 1);
  EXPECT_EQ(shaderDirectory(), dir.path());
  ::setenv("BOUNCE_SHADER_DIR", "/no/such/shader/folder", 1);
  try {
    shaderDirectory();
    FAIL() << "no error";
  } catch (const ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/shader/folder"), std::string::npos);
  }
  ::unsetenv("BOUNCE_SHADER_DIR");
  // Unset: the build copies shaders/ next to the executables, this test's included.
  EXPECT_TRUE(std::filesystem::exists(shaderDirectory() / "forward.frag"));
}

// Readback is top row first: a shader lights the lower half of the target (gl_FragCoord.y
// counts from the bottom), which must come back as the image's last rows.
TEST(RenderTarget, ReadbackIsTopRowFirst) {
  testContext();
  const ScratchDir dir("readback");
  const auto fragment =
      dir.write("lower_half.frag",
                "#version 330 core\n"
                "out vec4 color;\n"
                "void main() { color = vec4(gl_FragCoord.y < 4.0 ? 1.0 : 0.0); }\n");
  Program program(shaderDirectory() / "fullscreen.vert", fragment);
  RenderTarget target(3, 8);
  target.bind();
  clear(glm::vec4(0.0f));
  program.use();
  drawFullscreenTriangle();
  const Image image = target.read();
  for (int y = 0; y < 8; ++y) EXPECT_EQ(image.at(1, y).r, y >= 4 ? 1.0f : 0.0f) << "row " << y;
}

}  // namespace
}  // namespace bounce::gl::test
