// Triangles on the GPU: one vertex buffer, one index buffer and the vertex array that reads them
// as attributes 0 = position, 1 = normal, 2 = uv (the layout shaders/forward.vert declares).
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace bounce::gl {

struct Vertex {
  glm::vec3 position;  // metres
  glm::vec3 normal;    // unit
  glm::vec2 uv;
};

class MeshBuffer {
 public:
  MeshBuffer(std::span<const Vertex> vertices, std::span<const uint32_t> indices);
  ~MeshBuffer();
  MeshBuffer(const MeshBuffer&) = delete;
  MeshBuffer& operator=(const MeshBuffer&) = delete;

  // Draws `indexCount` indices (3 per triangle) from `firstIndex`.
  void draw(uint32_t firstIndex, uint32_t indexCount) const;
  uint32_t indexCount() const { return indexCount_; }

 private:
  uint32_t vertexArray_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0, indexCount_ = 0;
};

}  // namespace bounce::gl
