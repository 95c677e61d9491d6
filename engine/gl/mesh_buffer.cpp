#include "gl/mesh_buffer.h"

#include <cstddef>

#include "gl/gl_functions.h"

namespace bounce::gl {

MeshBuffer::MeshBuffer(std::span<const Vertex> vertices, std::span<const uint32_t> indices)
    : indexCount_(static_cast<uint32_t>(indices.size())) {
  glGenVertexArrays(1, &vertexArray_);
  glBindVertexArray(vertexArray_);
  glGenBuffers(1, &vertexBuffer_);
  glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size_bytes()), vertices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &indexBuffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size_bytes()),
               indices.data(), GL_STATIC_DRAW);
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  const auto attribute = [&](GLuint index, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(Vertex, position));
  attribute(1, 3, offsetof(Vertex, normal));
  attribute(2, 2, offsetof(Vertex, uv));
  glBindVertexArray(0);
}

MeshBuffer::~MeshBuffer() {
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteBuffers(1, &vertexBuffer_);
  glDeleteBuffers(1, &indexBuffer_);
}

void MeshBuffer::draw(uint32_t firstIndex, uint32_t indexCount) const {
  if (indexCount == 0) return;
  glBindVertexArray(vertexArray_);
  glDrawElements(
      GL_TRIANGLES, static_cast<GLsizei>(indexCount), GL_UNSIGNED_INT,
      reinterpret_cast<const void*>(static_cast<std::size_t>(firstIndex) * sizeof(uint32_t)));
  glBindVertexArray(0);
}

}  // namespace bounce::gl
