// One instance as the passes draw it: its mesh, material and model matrix (moving it re-uploads
// nothing but its matrices), its world box for culling and its vertex array. Apart from
// gpu_scene.h so that what only reads the instances (shadow_map_stamp.h) needs no GL scene.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/mesh_buffer.h"
#include "scene/box.h"
#include "scene/scene.h"

namespace bounce {

struct GpuInstance {
  uint32_t mesh = 0;
  uint32_t material = 0;  // into GpuScene::materials(); the absorber for a bad index
  Mobility mobility = Mobility::Static;
  glm::mat4 model{1.0f};         // object → world
  glm::mat3 normalMatrix{1.0f};  // inverse transpose of model's linear part
  bool mirrored = false;         // det < 0: winding flips, so culling flips
  Box worldBox;                  // metres
  gl::VertexArray vertexArray;
  // A sphere around its world vertices: centre (m) and radius (m), from its mesh's sphere about
  // the mesh box's centre, the radius scaled by the transform's largest axis scale.
  glm::vec4 worldSphere{0.0f};
};

}  // namespace bounce
