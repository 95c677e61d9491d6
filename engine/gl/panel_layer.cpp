#include "gl/panel_layer.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gl/context.h"
#include "gl/window_glfw_impl.h"

namespace bounce::gl {

PanelLayer::PanelLayer(Window& window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written beside the user's files
  ImGui::StyleColorsDark();
  if (!ImGui_ImplGlfw_InitForOpenGL(window.impl_->window, true)) {
    ImGui::DestroyContext();
    throw ContextError("imgui: the GLFW back-end did not start");
  }
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw ContextError("imgui: the OpenGL 3 back-end did not start");
  }
}

PanelLayer::~PanelLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void PanelLayer::beginFrame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void PanelLayer::endFrame() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool PanelLayer::wantsKeyboard() const {
  return ImGui::GetIO().WantCaptureKeyboard;
}

bool PanelLayer::wantsMouse() const {
  return ImGui::GetIO().WantCaptureMouse;
}

}  // namespace bounce::gl
