// GLFW backend. GLFW is initialized with the first window and terminated with the last.
#include <array>
#include <utility>

#include "gl/gl_functions.h"
#include "gl/window.h"
#include "gl/window_glfw_impl.h"

namespace bounce::gl {

namespace {

std::string lastGlfwError;

void recordGlfwError(int, const char* description) {
  lastGlfwError = description;
}

GLADapiproc glfwProc(const char* name) {
  return glfwGetProcAddress(name);
}

constexpr std::array<std::pair<Key, int>, 37> kKeyCodes = {{
    {Key::W, GLFW_KEY_W},
    {Key::A, GLFW_KEY_A},
    {Key::S, GLFW_KEY_S},
    {Key::D, GLFW_KEY_D},
    {Key::Q, GLFW_KEY_Q},
    {Key::E, GLFW_KEY_E},
    {Key::Tab, GLFW_KEY_TAB},
    {Key::F12, GLFW_KEY_F12},
    {Key::Escape, GLFW_KEY_ESCAPE},
    {Key::Plus, GLFW_KEY_EQUAL},
    {Key::Minus, GLFW_KEY_MINUS},
    {Key::LeftShift, GLFW_KEY_LEFT_SHIFT},
    {Key::LeftBracket, GLFW_KEY_LEFT_BRACKET},
    {Key::RightBracket, GLFW_KEY_RIGHT_BRACKET},
    {Key::Digit1, GLFW_KEY_1},
    {Key::Digit2, GLFW_KEY_2},
    {Key::Digit3, GLFW_KEY_3},
    {Key::Digit4, GLFW_KEY_4},
    {Key::Digit5, GLFW_KEY_5},
    {Key::Digit6, GLFW_KEY_6},
    {Key::Digit7, GLFW_KEY_7},
    {Key::Digit8, GLFW_KEY_8},
    {Key::Digit9, GLFW_KEY_9},
    {Key::M, GLFW_KEY_M},
    {Key::C, GLFW_KEY_C},
    {Key::G, GLFW_KEY_G},
    {Key::I, GLFW_KEY_I},
    {Key::K, GLFW_KEY_K},
    {Key::J, GLFW_KEY_J},
    {Key::L, GLFW_KEY_L},
    {Key::U, GLFW_KEY_U},
    {Key::O, GLFW_KEY_O},
    {Key::H, GLFW_KEY_H},
    {Key::F1, GLFW_KEY_F1},
    {Key::F2, GLFW_KEY_F2},
    {Key::F3, GLFW_KEY_F3},
    {Key::F4, GLFW_KEY_F4},
}};

int glfwKey(Key key) {
  for (const auto& [k, code] : kKeyCodes)
    if (k == key) return code;
  return GLFW_KEY_UNKNOWN;
}

}  // namespace

int WindowGlfwCount::windows = 0;

struct WindowCallbacks {
  static void key(GLFWwindow* w, int key, int, int action, int) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
    if (action != GLFW_PRESS) return;
    // The keypad's + and - count as the speed keys too.
    if (key == GLFW_KEY_KP_ADD) key = GLFW_KEY_EQUAL;
    if (key == GLFW_KEY_KP_SUBTRACT) key = GLFW_KEY_MINUS;
    for (const auto& [k, code] : kKeyCodes)
      if (code == key) self->pressed_.push_back(k);
  }
  static void scroll(GLFWwindow* w, double, double dy) {
    static_cast<Window*>(glfwGetWindowUserPointer(w))->scroll_ += dy;
  }
};

Window::Window(const std::string& title, int width, int height) : impl_(std::make_unique<Impl>()) {
  glfwSetErrorCallback(recordGlfwError);
  if (WindowGlfwCount::windows == 0 && !glfwInit()) {
    throw ContextError("glfw: cannot initialize (" + lastGlfwError + ")");
  }
  ++WindowGlfwCount::windows;
  impl_->holdsGlfw = true;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  impl_->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!impl_->window) {  // impl_'s destructor releases GLFW
    throw ContextError("glfw: cannot open a window with an OpenGL 3.3 core context (" +
                       lastGlfwError + ")");
  }
  glfwSetWindowUserPointer(impl_->window, this);
  glfwSetKeyCallback(impl_->window, WindowCallbacks::key);
  glfwSetScrollCallback(impl_->window, WindowCallbacks::scroll);
  glfwMakeContextCurrent(impl_->window);
  glfwSwapInterval(0);              // frame times measure rendering, not the display's refresh
  loadGlFunctions(this, glfwProc);  // may throw: impl_ then destroys the window
}

Window::~Window() {
  forgetGlFunctions(this);  // then impl_ destroys the window and releases GLFW
}

void Window::makeCurrent() {
  glfwMakeContextCurrent(impl_->window);
  loadGlFunctions(this, glfwProc);
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(impl_->window);
}
void Window::requestClose() {
  glfwSetWindowShouldClose(impl_->window, GLFW_TRUE);
}

void Window::pollEvents() {
  pressed_.clear();
  scroll_ = 0.0;
  glfwPollEvents();
}

void Window::swapBuffers() {
  glfwSwapBuffers(impl_->window);
}
void Window::setTitle(const std::string& title) {
  glfwSetWindowTitle(impl_->window, title.c_str());
}

glm::ivec2 Window::framebufferSize() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(impl_->window, &size.x, &size.y);
  return size;
}

bool Window::isDown(Key key) const {
  return glfwGetKey(impl_->window, glfwKey(key)) == GLFW_PRESS;
}

bool Window::isDown(MouseButton button) const {
  return glfwGetMouseButton(impl_->window, button == MouseButton::Left
                                               ? GLFW_MOUSE_BUTTON_LEFT
                                               : GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
}

glm::dvec2 Window::cursorPosition() const {
  glm::dvec2 p;
  glfwGetCursorPos(impl_->window, &p.x, &p.y);
  return p;
}

}  // namespace bounce::gl
