// A GLFW window with an OpenGL 3.3 core forward-compatible context (the viewer's backend), plus
// the keyboard and mouse input the fly camera reads. Keys are bounce's own enum, so no GLFW
// header is reachable from here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/context.h"

namespace bounce::gl {

enum class Key {
  W,
  A,
  S,
  D,
  Q,
  E,
  Tab,
  F12,
  Escape,
  Plus,
  Minus,
  LeftShift,
  LeftBracket,
  RightBracket,
  Digit1,
  Digit2,
  Digit3,
  Digit4,
  Digit5,
  Digit6,
  Digit7,
  Digit8,
  Digit9,
  M,   // bounce-view: next render mode
  C,   // bounce-view: chart view on/off
  G,   // bounce-view: select the next dynamic object
  I,   // bounce-view: move the selected object away from the camera
  K,   //   ... towards the camera
  J,   //   ... left
  L,   //   ... right
  U,   //   ... down
  O,   //   ... up
  H,   // bounce-view: panel shown/hidden
  F1,  // bounce-view: camera bookmark 1 (Shift: save it)
  F2,  //   ... 2
  F3,  //   ... 3
  F4,  //   ... 4
};

enum class MouseButton { Left, Right };

class Window final : public Context {
 public:
  // Opens the window and makes its context current; throws ContextError (no display, no 3.3).
  Window(const std::string& title, int width, int height);
  ~Window() override;

  ContextBackend backend() const override { return ContextBackend::GLFW; }
  void makeCurrent() override;

  bool shouldClose() const;
  void requestClose();
  // Processes window events; collects key presses and scrolling since the previous call.
  void pollEvents();
  void swapBuffers();
  void setTitle(const std::string& title);
  glm::ivec2 framebufferSize() const;  // pixels

  bool isDown(Key key) const;
  bool isDown(MouseButton button) const;
  const std::vector<Key>& pressedKeys() const { return pressed_; }  // since the last poll
  double scrolled() const { return scroll_; }                       // wheel steps since last poll
  glm::dvec2 cursorPosition() const;                                // screen units

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<Key> pressed_;
  double scroll_ = 0.0;
  friend struct WindowCallbacks;
  friend class PanelLayer;
};

}  // namespace bounce::gl
