// bounce-view's keys and mouse, read once a frame into what the user asked for (as the panel's
// ViewerPanelRequests): the viewer applies it. Keys:
//   W/A/S/D move, Q/E down/up, Shift ×4 speed, a drag with either mouse button looks around,
//   +/− or the wheel change the speed, Tab / 1–9 pick the scene's cameras, F12 saves a
//   screenshot, [ and ] change the exposure by 0.5 EV, Esc quits, H shows or hides the panel,
//   M cycles the modes, C toggles the chart view, F1–F4 return to a camera bookmark and
//   Shift+F1–F4 save one, G selects the next dynamic object and J/L, I/K, U/O move it
//   left/right, away/towards, down/up.
// Keys go to the panel only while it edits a field, the mouse while it is over the panel.
#pragma once

#include <cstddef>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/window.h"

namespace bounce {

struct ViewerInput {
  bool togglePanel = false;           // H
  bool quit = false;                  // Esc
  bool nextCamera = false;            // Tab
  std::optional<std::size_t> camera;  // 1–9: the scene's camera 0–8
  float speedFactor = 1.0f;           // the fly speed × this: +/− ×1.5, a wheel step ×1.25
  bool screenshot = false;            // F12
  float exposureStep = 0.0f;          // EV: [ −0.5, ] +0.5
  bool nextMode = false;              // M
  bool toggleCharts = false;          // C
  bool nextObject = false;            // G
  std::optional<std::size_t> saveBookmark, goToBookmark;  // slot 0–3: Shift+F1–F4, F1–F4
  glm::vec3 fly{0.0f};     // the camera's motion (right, up, forward), each −1, 0 or 1
  glm::vec3 object{0.0f};  // the selected object's motion (right, up, away), each −1, 0 or 1
  float boost = 1.0f;      // Shift: both motions ×4
  std::optional<glm::vec2> turn;  // (yaw, pitch) radians from a mouse drag
};

// Keeps the cursor between frames, so a drag turns by what it moved since the last one.
class ViewerControls {
 public:
  ViewerInput read(const gl::Window& window, bool panelHasKeys, bool panelHasMouse);

 private:
  std::optional<glm::dvec2> cursor_;
};

}  // namespace bounce
