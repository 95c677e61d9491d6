#include "gl/mesh_buffer.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_functions.h"
#include "gl/vertex_attributes.h"

namespace bounce::gl {
namespace {

uint32_t uploadBuffer(const void* data, std::size_t bytes) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return buffer;
}

}  // namespace

MeshBuffer::MeshBuffer(std::span<const Vertex> corners)
    : buffer_(uploadBuffer(corners.data(), corners.size_bytes())),
      cornerCount_(static_cast<uint32_t>(corners.size())) {}

MeshBuffer::~MeshBuffer() {
  glDeleteBuffers(1, &buffer_);
}

CornerAttribute::CornerAttribute(std::span<const glm::vec2> values)
    : buffer_(uploadBuffer(values.data(), values.size_bytes())),
      cornerCount_(static_cast<uint32_t>(values.size())) {}

CornerAttribute::~CornerAttribute() {
  glDeleteBuffers(1, &buffer_);
}

VertexArray::VertexArray(const MeshBuffer& mesh, const CornerAttribute* lightmapUv)
    : cornerCount_(mesh.cornerCount_) {
  glGenVertexArrays(1, &vertexArray_);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ARRAY_BUFFER, mesh.buffer_);
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  const auto attribute = [&](GLuint index, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset));
  };
  attribute(VertexAttribute::kPosition, 3, offsetof(Vertex, position));
  attribute(VertexAttribute::kNormal, 3, offsetof(Vertex, normal));
  attribute(VertexAttribute::kUv, 2, offsetof(Vertex, uv));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  setLightmapUv(lightmapUv);
}

VertexArray::~VertexArray() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

VertexArray::VertexArray(VertexArray&& other) noexcept
    : vertexArray_(std::exchange(other.vertexArray_, 0)),
      cornerCount_(other.cornerCount_),
      hasLightmapUv_(other.hasLightmapUv_) {}

void VertexArray::setLightmapUv(const CornerAttribute* lightmapUv) {
  if (lightmapUv && lightmapUv->cornerCount_ != cornerCount_)
    throw std::invalid_argument("lightmap UVs for " + std::to_string(lightmapUv->cornerCount_) +
                                " corners on a mesh of " + std::to_string(cornerCount_));
  glBindVertexArray(vertexArray_);
  if (lightmapUv) {
    glBindBuffer(GL_ARRAY_BUFFER, lightmapUv->buffer_);
    glEnableVertexAttribArray(VertexAttribute::kLightmapUv);
    glVertexAttribPointer(VertexAttribute::kLightmapUv, 2, GL_FLOAT, GL_FALSE,
                          static_cast<GLsizei>(sizeof(glm::vec2)), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  } else {
    glDisableVertexAttribArray(VertexAttribute::kLightmapUv);
  }
  glBindVertexArray(0);
  hasLightmapUv_ = lightmapUv != nullptr;
}

void VertexArray::draw() const {
  if (cornerCount_ == 0) return;
  glBindVertexArray(vertexArray_);
  // A disabled array reads the context's current generic value: make it (0,0) explicitly.
  if (!hasLightmapUv_) glVertexAttrib2f(VertexAttribute::kLightmapUv, 0.0f, 0.0f);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(cornerCount_));
  glBindVertexArray(0);
}

}  // namespace bounce::gl
