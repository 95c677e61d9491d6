// Contexts: OSMesa always works here (it is the tests' backend); EGL either yields a 3.3+ core
// context that renders, or reports clearly why not (then the test is skipped).
#include <gtest/gtest.h>

#include <string>

#include "gl/draw_state.h"
#include "gl/render_target.h"
#include "gl_test_support.h"

namespace bounce::gl::test {
namespace {

// GL_VERSION begins "major.minor"; bounce needs 3.3 core.
bool atLeast33(const std::string& version) {
  int major = 0, minor = 0;
  return std::sscanf(version.c_str(), "%d.%d", &major, &minor) == 2 && major * 10 + minor >= 33;
}

// Clears a small target to a colour and reads it back: the context really renders.
void expectClearReadsBack() {
  RenderTarget target(8, 4);
  target.bind();
  clear({0.25f, 2.5f, 100.0f, 1.0f});  // HDR values survive the float target unclamped
  const Image image = target.read();
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 4);
  for (const glm::vec3& p : image.pixels) EXPECT_EQ(p, glm::vec3(0.25f, 2.5f, 100.0f));
}

TEST(Context, OSMesaGivesCoreContextThatRenders) {
  const std::unique_ptr<Context> context = createOSMesaContext();
  EXPECT_EQ(context->backend(), ContextBackend::OSMesa);
  EXPECT_TRUE(atLeast33(context->version())) << context->version();
  EXPECT_NE(context->version().find("Core"), std::string::npos) << context->version();
  expectClearReadsBack();
}

TEST(Context, EglWorksOrReportsWhyNot) {
  std::unique_ptr<Context> context;
  try {
    context = createEglContext();
  } catch (const ContextError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("egl: ", 0), 0u) << message;  // names the backend
    GTEST_SKIP() << "no EGL display on this machine: " << message;
  }
  EXPECT_EQ(context->backend(), ContextBackend::EGL);
  EXPECT_TRUE(atLeast33(context->version())) << context->version();
  expectClearReadsBack();
}

TEST(Context, SwitchingBetweenBackendsKeepsEachUsable) {
  std::unique_ptr<Context> egl;
  try {
    egl = createEglContext();
  } catch (const ContextError& e) {
    GTEST_SKIP() << e.what();
  }
  testContext();
  expectClearReadsBack();
  egl->makeCurrent();
  expectClearReadsBack();
}

TEST(Context, OffscreenDefaultPicksEglOrSaysWhy) {
  std::string eglFailure;
  const auto context = createOffscreenContext(std::nullopt, &eglFailure);
  if (context->backend() == ContextBackend::OSMesa)
    EXPECT_FALSE(eglFailure.empty());
  else
    EXPECT_TRUE(eglFailure.empty());
  expectClearReadsBack();
  EXPECT_THROW(createOffscreenContext(ContextBackend::GLFW), ContextError);
}

TEST(RenderTarget, RejectsImpossibleSizes) {
  testContext();
  EXPECT_THROW(RenderTarget(0, 4), std::invalid_argument);
  EXPECT_THROW(RenderTarget(4, 1 << 20), std::invalid_argument);
}

}  // namespace
}  // namespace bounce::gl::test
