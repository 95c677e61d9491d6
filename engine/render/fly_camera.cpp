#include "render/fly_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {
constexpr float kMaxPitch = 1.5533430f;  // 89°, keeps forward away from world up
}

FlyCamera::FlyCamera(const Camera& camera) : lens_(camera), position_(camera.position()) {
  const glm::vec3 f = camera.forward();
  pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(-f.x, -f.z);
}

glm::vec3 FlyCamera::forward() const {
  return {-std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
}

void FlyCamera::move(glm::vec3 d) {
  const glm::vec3 up(0, 1, 0);
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::cross(f, up));
  position_ += d.x * right + d.y * up + d.z * f;
}

void FlyCamera::turn(float yaw, float pitch) {
  yaw_ += yaw;
  pitch_ = std::clamp(pitch_ + pitch, -kMaxPitch, kMaxPitch);
}

Camera FlyCamera::camera() const {
  Camera camera = lens_;
  camera.cameraToWorld =
      glm::inverse(glm::lookAt(position_, position_ + forward(), glm::vec3(0, 1, 0)));
  return camera;
}

}  // namespace bounce
