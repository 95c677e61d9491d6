// Dear ImGui (Debian's libimgui-dev with its GLFW and OpenGL 3 back-ends) on a gl::Window: the
// viewer's panel. Widgets are plain ImGui:: calls between beginFrame() and endFrame(); this
// layer owns the ImGui context and the back-ends, which install their input callbacks after
// the window's own and pass every event on to them (so the window's keys keep working).
// endFrame() draws into the framebuffer bound at the time (the window's, after tone mapping):
// never into a render target, so captures hold the scene's frame only.
#pragma once

namespace bounce::gl {

class Window;

class PanelLayer {
 public:
  explicit PanelLayer(Window& window);  // throws ContextError when a back-end cannot start
  ~PanelLayer();
  PanelLayer(const PanelLayer&) = delete;
  PanelLayer& operator=(const PanelLayer&) = delete;

  void beginFrame();
  void endFrame();
  // Whether the panel has the keyboard (a text field) or the mouse (the cursor over a window
  // of the panel): the viewer then leaves those events to it.
  bool wantsKeyboard() const;
  bool wantsMouse() const;
};

}  // namespace bounce::gl
