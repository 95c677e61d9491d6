// From a scene camera to the matrices a pass draws with, and a camera framing a scene that has
// none. GL-free.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

struct Bounds {
  glm::vec3 lo{0.0f}, hi{0.0f};  // metres, world
  bool empty = true;
};

// World bounds of every instance's vertices.
Bounds sceneBounds(const Scene& scene);

// World → clip space of a pinhole camera for an image of aspect width/height; the camera's own
// aspect is ignored (the image decides). OpenGL clip conventions (depth −1..1).
glm::mat4 viewProjection(const Camera& camera, float aspect);

// A camera on the +Z side of the bounds, looking down −Z at their centre, far enough that the
// bounding sphere fits in both fields of view. An empty `bounds` gives a camera at (0,0,1).
Camera frameBounds(const Bounds& bounds, float aspect);

}  // namespace bounce
