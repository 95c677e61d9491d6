// Triangles on the GPU, uploaded once and drawn with any model matrix:
//   MeshBuffer      one mesh's corners (position, normal, uv), de-indexed: 3 per triangle in the
//                   order of the mesh's `indices`, attributes 0..2 of vertex_attributes.h;
//   CornerAttribute one vec2 per corner of a mesh (e.g. an instance's lightmap UVs);
//   VertexArray     what one draw reads: a MeshBuffer plus, optionally, a CornerAttribute at
//                   location 3 (absent: the attribute reads the constant (0,0)).
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace bounce::gl {

struct Vertex {
  glm::vec3 position;  // metres, object space
  glm::vec3 normal;    // unit, object space
  glm::vec2 uv;
};

class MeshBuffer {
 public:
  explicit MeshBuffer(std::span<const Vertex> corners);
  ~MeshBuffer();
  MeshBuffer(const MeshBuffer&) = delete;
  MeshBuffer& operator=(const MeshBuffer&) = delete;

  uint32_t cornerCount() const { return cornerCount_; }

 private:
  friend class VertexArray;
  uint32_t buffer_ = 0, cornerCount_ = 0;
};

class CornerAttribute {
 public:
  explicit CornerAttribute(std::span<const glm::vec2> values);
  ~CornerAttribute();
  CornerAttribute(const CornerAttribute&) = delete;
  CornerAttribute& operator=(const CornerAttribute&) = delete;

  uint32_t cornerCount() const { return cornerCount_; }

 private:
  friend class VertexArray;
  uint32_t buffer_ = 0, cornerCount_ = 0;
};

class VertexArray {
 public:
  // Both must outlive the VertexArray. Throws std::invalid_argument when `lightmapUv` has a
  // different corner count from `mesh`.
  explicit VertexArray(const MeshBuffer& mesh, const CornerAttribute* lightmapUv = nullptr);
  ~VertexArray();
  VertexArray(VertexArray&& other) noexcept;
  VertexArray& operator=(VertexArray&&) = delete;
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;

  // Replaces (or removes, with nullptr) the per-corner attribute at location 3.
  void setLightmapUv(const CornerAttribute* lightmapUv);
  // Draws every triangle of the mesh.
  void draw() const;
  uint32_t cornerCount() const { return cornerCount_; }

 private:
  uint32_t vertexArray_ = 0, cornerCount_ = 0;
  bool hasLightmapUv_ = false;
};

}  // namespace bounce::gl
