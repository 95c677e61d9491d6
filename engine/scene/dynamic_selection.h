// Which dynamic object the viewer moves, and where to: bounce-view's object controls without
// GL or a window, so they can be tested. GL-free.
//
// The selection cycles through the scene's dynamic instances by name (an instance name stands
// for all instances of one glTF node, engine/scene/instance_move.h). Moves go through
// moveInstance, the rule --move uses in bounce-render and bounce-trace, so the viewer, the
// renderer and the path tracer place an object the same way.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace bounce {

class DynamicSelection {
 public:
  // Selects the first dynamic instance, if the scene has one.
  explicit DynamicSelection(const Scene& scene);

  bool empty() const { return heads_.empty(); }
  std::size_t count() const { return heads_.size(); }
  // The next dynamic object (wrapping); nothing when there is none.
  void selectNext();
  // The selected object's name; empty when the scene has no dynamic instance.
  std::string name(const Scene& scene) const;
  // World translation of the selected object (m); zero when there is none.
  glm::vec3 translation(const Scene& scene) const;

  // Moves the selected object by `delta` (world, m) in `scene` and returns the indices of the
  // instances whose transforms changed (for ForwardRenderer::setInstanceTransform).
  std::vector<std::size_t> move(Scene& scene, const glm::vec3& delta) const;

 private:
  std::vector<std::size_t> heads_;  // one instance index per dynamic name
  std::size_t selected_ = 0;
};

// The signed world axis (±x, ±y or ±z, unit) nearest to `direction`; ties go to x, then y.
// The viewer moves an object along the axis nearest the camera's right, up and forward, so the
// keys follow the screen and the object stays on the room's grid.
glm::vec3 nearestAxis(const glm::vec3& direction);

// How fast the viewer moves an object, m/s: a quarter of the scene's bounding-box diagonal per
// second (at least 0.1 m/s), as the fly camera's speed.
float objectSpeed(const Scene& scene);

}  // namespace bounce
