#include "viewer_input.h"

#include <cmath>

namespace bounce {

namespace {

constexpr float kRadiansPerPixel = 0.003f;  // a drag's turn
constexpr float kBoost = 4.0f;              // Shift

using gl::Key;

void readKey(Key key, const gl::Window& window, ViewerInput& in) {
  if (key == Key::H) in.togglePanel = true;
  if (key == Key::Escape) in.quit = true;
  if (key == Key::Tab) in.nextCamera = true;
  if (key >= Key::Digit1 && key <= Key::Digit9)
    in.camera = static_cast<std::size_t>(static_cast<int>(key) - static_cast<int>(Key::Digit1));
  if (key == Key::Plus) in.speedFactor *= 1.5f;
  if (key == Key::Minus) in.speedFactor /= 1.5f;
  if (key == Key::F12) in.screenshot = true;
  if (key == Key::LeftBracket) in.exposureStep -= 0.5f;
  if (key == Key::RightBracket) in.exposureStep += 0.5f;
  if (key == Key::M) in.nextMode = true;
  if (key == Key::C) in.toggleCharts = true;
  if (key == Key::G) in.nextObject = true;
  if (key >= Key::F1 && key <= Key::F4) {
    const auto slot = static_cast<std::size_t>(static_cast<int>(key) - static_cast<int>(Key::F1));
    if (window.isDown(Key::LeftShift))
      in.saveBookmark = slot;
    else
      in.goToBookmark = slot;
  }
}

}  // namespace

ViewerInput ViewerControls::read(const gl::Window& window, bool panelHasKeys, bool panelHasMouse) {
  ViewerInput in;
  if (!panelHasKeys)
    for (const Key key : window.pressedKeys()) readKey(key, window, in);
  in.speedFactor *= std::pow(1.25f, static_cast<float>(window.scrolled()));
  const auto axis = [&](Key plus, Key minus) {
    return (window.isDown(plus) ? 1.0f : 0.0f) - (window.isDown(minus) ? 1.0f : 0.0f);
  };
  in.fly = glm::vec3(axis(Key::D, Key::A), axis(Key::E, Key::Q), axis(Key::W, Key::S));
  in.object = glm::vec3(axis(Key::L, Key::J), axis(Key::O, Key::U), axis(Key::I, Key::K));
  in.boost = window.isDown(Key::LeftShift) ? kBoost : 1.0f;
  const glm::dvec2 cursor = window.cursorPosition();
  const bool looking = !panelHasMouse && (window.isDown(gl::MouseButton::Left) ||
                                          window.isDown(gl::MouseButton::Right));
  if (looking && cursor_) {
    const glm::dvec2 delta = cursor - *cursor_;
    in.turn =
        glm::vec2(-static_cast<float>(delta.x), -static_cast<float>(delta.y)) * kRadiansPerPixel;
  }
  cursor_ = cursor;
  return in;
}

}  // namespace bounce
