// The viewer's fly camera: a position and a heading (yaw about world +Y, pitch above the
// horizon), moved in metres and turned in radians. GL-free.
#pragma once

#include "scene/scene.h"

namespace bounce {

class FlyCamera {
 public:
  // Starts where `camera` is, looking where it looks (its roll is dropped), with its lens.
  explicit FlyCamera(const Camera& camera);

  // Moves by `metres` along the camera's right, world up, and forward directions.
  void move(glm::vec3 rightUpForward);
  // Turns left by `yaw` and up by `pitch` radians; pitch stays within ±89°.
  void turn(float yaw, float pitch);

  glm::vec3 position() const { return position_; }
  glm::vec3 forward() const;
  Camera camera() const;

 private:
  Camera lens_;
  glm::vec3 position_;
  float yaw_ = 0.0f;    // 0 looks down −Z; positive turns towards −X (left)
  float pitch_ = 0.0f;  // positive looks up
};

}  // namespace bounce
