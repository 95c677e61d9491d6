// The VPLs' light on the dynamic instances, gathered where it is cheap: a dynamic pixel's cost
// must not grow with the VPL count. Each frame, for every dynamic instance, the VPLs' irradiance
// E (W/m², clamped, with their shadow cubes: exactly the sum a pixel would take, shaders/vpl.glsl)
// is gathered at each vertex of its mesh for the vertex's shading normal (shaders/
// vpl_vertex_light.frag: one fragment per vertex, into an RGBA32F target kVplVertexLightWidth
// texels wide, each instance's vertices from a row of their own). forward.vert reads its
// corner's vertex and the pixels interpolate E over the triangle, as Gouraud shading does: the
// VPL count is paid once per vertex and frame, not per pixel.
//
// Interpolation is off where E curves within a triangle, which grows as (h/d)², h the longest
// edge and d the distance to the nearest light that lit a corner (VPLs sit on the surfaces that
// light the object: d is how far the light's source is). A triangle with h >
// kVplMaxEdgeOverDistance · min d (forward.geom), a back face (its E is for the other side) and
// every pixel in the vpl modes gather the VPLs themselves. The vertex pass costs the instances'
// vertex count in gathers: far cheaper than their pixels for a mesh finer than its screen footprint
// (the Cornell sphere: 1,153 vertices, tens of thousands of pixels at 1920 × 1080), and no dearer
// than the pixels' gather otherwise. GL calls only through engine/gl.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/render_target.h"
#include "gl/shader.h"
#include "gl/texture_buffer.h"
#include "scene/scene.h"

namespace bounce {

class GpuScene;
class LightTable;
class VplPass;

inline constexpr int kVplVertexLightWidth = 256;        // texels per row of the vertex target
inline constexpr float kVplMaxEdgeOverDistance = 0.5f;  // h / d above which a triangle gathers

class VplVertexLight {
 public:
  // Uploads the meshes of `scene`'s dynamic instances (positions and normals in object space,
  // and the corner → vertex table of their de-indexed draws). Needs a current GL context.
  VplVertexLight(const Scene& scene, const std::filesystem::path& shaderDir);

  // Gathers the VPLs of `vpls` (attached; `table` holds their sections, updated) at the
  // vertices of every dynamic instance of `scene`, unless nothing it depends on changed since
  // the last gather (no instance moved: the VPLs' shadow cubes hold them all; the same VPLs,
  // VplPass::version). Changes the bound framebuffer and viewport when it gathers.
  void render(const GpuScene& scene, const LightTable& table, const VplPass& vpls);
  // How many frames gathered: a still scene's do not.
  uint64_t gathers() const { return gathers_; }
  // Forgets the last gather: no draw reads vertex light.
  void clear();

  // Per frame: both texture units (stand-ins when nothing was gathered).
  void bind(gl::Program& program) const;
  // Per draw: whether instance `index` reads its vertices' light, and where.
  void setInstance(gl::Program& program, const GpuScene& scene, std::size_t index) const;
  bool gathered(std::size_t index) const { return index < rowOf_.size() && rowOf_[index] >= 0; }

 private:
  struct MeshTables {
    gl::TextureBuffer vertices;  // 2 texels per vertex: position (m), unit normal; object space
    gl::TextureBuffer corners;   // per corner of the draw: (its vertex, 0)
    int vertexCount = 0;
  };
  gl::Program program_;
  std::vector<std::optional<MeshTables>> meshes_;  // per scene mesh: those of dynamic instances
  gl::TextureBuffer noCorners_;                    // the stand-in corner table
  std::optional<gl::RenderTarget> target_;
  std::vector<int> rowOf_;  // per instance: its first row, −1 for none
  // What the last gather saw: every instance's model and the VPLs' version (none: gather).
  std::vector<glm::mat4> gatheredModels_;
  std::optional<uint64_t> gatheredVersion_;
  uint64_t gathers_ = 0;
};

}  // namespace bounce
