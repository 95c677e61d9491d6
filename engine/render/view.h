// From a scene camera to the matrices a pass draws with. GL-free.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

// World → clip space of a pinhole camera for an image of aspect width/height; the camera's own
// aspect is ignored (the image decides). OpenGL clip conventions (depth −1..1).
glm::mat4 viewProjection(const Camera& camera, float aspect);

}  // namespace bounce
