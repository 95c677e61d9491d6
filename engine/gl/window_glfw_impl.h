// The GLFW side of gl::Window, private to the GL layer (window_glfw.cpp and the panel layer,
// panel_layer.cpp, which hands the window to Dear ImGui's GLFW back-end).
#pragma once

// glad/gl.h first (gl_functions.h): GLFW must not include the system GL header.
#include "gl/gl_functions.h"
#include "gl/window.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace bounce::gl {

// How many windows hold the GLFW library: initialized with the first, terminated with the last.
struct WindowGlfwCount {
  static int windows;
};

// Owns the GLFW window and one reference on the GLFW library, so a constructor that throws
// part-way (no window, no GL 3.3 functions) destroys what it made and keeps the count right.
struct Window::Impl {
  bool holdsGlfw = false;
  GLFWwindow* window = nullptr;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (window) glfwDestroyWindow(window);
    if (holdsGlfw && --WindowGlfwCount::windows == 0) glfwTerminate();
  }
};

}  // namespace bounce::gl
