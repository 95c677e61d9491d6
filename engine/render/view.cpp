#include "render/view.h"

#include <glm/gtc/matrix_transform.hpp>

namespace bounce {

glm::mat4 viewProjection(const Camera& camera, float aspect) {
  return glm::perspective(camera.yfov, aspect, camera.znear, camera.zfar) *
         glm::inverse(camera.cameraToWorld);
}

}  // namespace bounce
