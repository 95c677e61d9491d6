// The GL context every GL test in a process shares. OSMesa (llvmpipe) unless the environment
// sets BOUNCE_TEST_GL=egl, which runs the same tests on the machine's EGL driver (a real GPU
// where there is one): llvmpipe forgives what real drivers do not, so the suite is run there too.
// Anything else in BOUNCE_TEST_GL is an error, not a silent fallback to OSMesa.
#pragma once

#include <cstdlib>
#include <memory>
#include <string>

#include "gl/context.h"

namespace bounce::test {

// "osmesa" or "egl": the backend the tests use, also for the tools they run (--context).
inline std::string testBackendName() {
  const char* chosen = std::getenv("BOUNCE_TEST_GL");
  const std::string backend = chosen && *chosen ? chosen : "osmesa";
  if (backend != "osmesa" && backend != "egl")
    throw gl::ContextError("BOUNCE_TEST_GL='" + backend + "': expected osmesa or egl");
  return backend;
}

inline std::unique_ptr<gl::Context> createTestContext() {
  return testBackendName() == "egl" ? gl::createEglContext() : gl::createOSMesaContext();
}

// One context per test process (gtest_discover_tests runs each test on its own), made current.
inline gl::Context& testContext() {
  static std::unique_ptr<gl::Context> context = createTestContext();
  context->makeCurrent();
  return *context;
}

}  // namespace bounce::test
