// Validated reads of glTF accessors. Every index, byte range and value is checked against the
// model, because tinygltf does not: a bad file throws LoadError, it never reads out of bounds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tinygltf {
class Model;
}

namespace bounce {

class GltfAccessors {
 public:
  GltfAccessors(const tinygltf::Model& model, std::filesystem::path file)
      : model_(model), file_(std::move(file)) {}

  // VEC3 of FLOAT; every value finite. `what` names the use in messages ("POSITION").
  std::vector<glm::vec3> readVec3(int accessor, const std::string& what) const;
  // VEC2 of FLOAT, or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT (texture coordinates).
  std::vector<glm::vec2> readVec2(int accessor, const std::string& what) const;
  // SCALAR of UNSIGNED_BYTE/SHORT/INT; every index < vertexCount.
  std::vector<uint32_t> readIndices(int accessor, std::size_t vertexCount,
                                    const std::string& what) const;

 private:
  struct Span {
    const unsigned char* data;  // first element
    std::size_t stride;         // bytes between elements
    std::size_t count;
    int componentType;
    bool normalized;
  };
  // Resolves accessor → bufferView → buffer and checks every byte of it lies in the buffer.
  Span resolve(int accessor, int type, const std::string& what) const;
  [[noreturn]] void fail(const std::string& reason) const;

  const tinygltf::Model& model_;
  std::filesystem::path file_;
};

}  // namespace bounce
