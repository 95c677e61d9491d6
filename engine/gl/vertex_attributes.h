// The vertex attribute locations every scene shader declares (`layout(location = N)` in
// shaders/forward.vert and shaders/shadow_depth.vert) and the GL layer binds. One table, here:
//
//   location  type  source                                   meaning
//   0         vec3  MeshBuffer (per mesh, uploaded once)     object-space position, metres
//   1         vec3  MeshBuffer                               object-space unit shading normal
//   2         vec2  MeshBuffer                               material UV (uv0)
//   3         vec2  CornerAttribute (per instance, optional) lightmap atlas UV; (0,0) when absent
//
// Meshes are uploaded de-indexed: vertex k of a MeshBuffer is corner k of the mesh's `indices`
// (corner 3t+c is corner c of triangle t), so a per-corner attribute such as
// LightmapLayout::cornerUv (engine/bake_folder/lightmap_layout.h) lines up with it one to one.
#pragma once

#include <cstdint>

namespace bounce::gl {

struct VertexAttribute {
  static constexpr uint32_t kPosition = 0;
  static constexpr uint32_t kNormal = 1;
  static constexpr uint32_t kUv = 2;
  static constexpr uint32_t kLightmapUv = 3;
};

}  // namespace bounce::gl
