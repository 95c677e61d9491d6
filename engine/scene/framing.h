// Where a scene is, and a camera that frames it when the file brings none (OBJ files never
// do). GL-free: the renderer, the viewer and the path tracer frame camera-less scenes alike.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

struct Bounds {
  glm::vec3 lo{0.0f}, hi{0.0f};  // metres, world
  bool empty = true;
};

// World bounds of every instance's vertices.
Bounds sceneBounds(const Scene& scene);

// A camera on the +Z side of the bounds, looking down −Z at their centre, far enough that the
// bounding sphere fits in both fields of view. An empty `bounds` (a scene with no vertices)
// gives a camera at (0,0,1) looking down −Z at the origin, with Camera's default clip range.
Camera frameBounds(const Bounds& bounds, float aspect);

// The camera a tool renders from: the one called `name` (std::invalid_argument when the scene
// has none of that name), else the scene's first, else one framing the scene's bounds for an
// image of width/height `aspect`; `framed` (optional) tells the caller to warn about the last.
Camera pickCamera(const Scene& scene, const std::string& name, float aspect, bool* framed);

}  // namespace bounce
