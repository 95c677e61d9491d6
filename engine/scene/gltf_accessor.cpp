#include "scene/gltf_accessor.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "io/load_error.h"

namespace bounce {
namespace {

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

std::size_t componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    default:
      return "another type";
  }
}

float readFloat(const unsigned char* p) {
  float v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

}  // namespace

void GltfAccessors::fail(const std::string& reason) const {
  throw LoadError(file_, reason);
}

GltfAccessors::Span GltfAccessors::resolve(int accessorIndex, int type,
                                           const std::string& what) const {
  const std::string where = what + " accessor " + std::to_string(accessorIndex);
  if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= model_.accessors.size()) {
    fail(where + " is out of range (the file has " + std::to_string(model_.accessors.size()) +
         " accessors)");
  }
  const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(accessorIndex)];
  if (accessor.sparse.isSparse) fail(where + " is sparse, which bounce does not support");
  if (accessor.type != type) fail(where + " is not " + typeName(type));
  const std::size_t elementSize = componentSize(accessor.componentType) * componentCount(type);
  if (elementSize == 0) fail(where + " has an invalid componentType");
  if (accessor.bufferView < 0 ||
      static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size()) {
    fail(where + ": bufferView " + std::to_string(accessor.bufferView) + " is out of range");
  }
  const tinygltf::BufferView& view =
      model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
    fail(where + ": buffer " + std::to_string(view.buffer) + " is out of range");
  }
  const tinygltf::Buffer& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)];
  // The view lies inside its buffer (a truncated .bin or .glb makes the buffer shorter).
  if (view.byteOffset > buffer.data.size() ||
      view.byteLength > buffer.data.size() - view.byteOffset) {
    fail(where + ": bufferView " + std::to_string(accessor.bufferView) + " (bytes " +
         std::to_string(view.byteOffset) + "+" + std::to_string(view.byteLength) +
         ") exceeds buffer " + std::to_string(view.buffer) + " of " +
         std::to_string(buffer.data.size()) + " bytes (truncated file?)");
  }
  const std::size_t stride = view.byteStride == 0 ? elementSize : view.byteStride;
  if (stride < elementSize) fail(where + ": byteStride is smaller than one element");
  // The accessor's last element ends inside the view.
  if (accessor.count > 0) {
    const std::size_t span = accessor.byteOffset + stride * (accessor.count - 1) + elementSize;
    if (accessor.byteOffset > view.byteLength || (accessor.count - 1) > view.byteLength / stride ||
        span > view.byteLength) {
      fail(where + " (" + std::to_string(accessor.count) + " elements) exceeds its bufferView");
    }
  }
  return Span{buffer.data.data() + view.byteOffset + accessor.byteOffset, stride, accessor.count,
              accessor.componentType, accessor.normalized};
}

std::vector<glm::vec3> GltfAccessors::readVec3(int accessor, const std::string& what) const {
  const Span s = resolve(accessor, TINYGLTF_TYPE_VEC3, what);
  if (s.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) fail(what + " is not FLOAT");
  std::vector<glm::vec3> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    const unsigned char* p = s.data + i * s.stride;
    out[i] = glm::vec3(readFloat(p), readFloat(p + 4), readFloat(p + 8));
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z)) {
      fail(what + " element " + std::to_string(i) + " is not finite (NaN or Inf)");
    }
  }
  return out;
}

std::vector<glm::vec2> GltfAccessors::readVec2(int accessor, const std::string& what) const {
  const Span s = resolve(accessor, TINYGLTF_TYPE_VEC2, what);
  std::vector<glm::vec2> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    const unsigned char* p = s.data + i * s.stride;
    switch (s.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        out[i] = glm::vec2(readFloat(p), readFloat(p + 4));
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        if (!s.normalized) fail(what + " of UNSIGNED_BYTE must be normalized");
        out[i] = glm::vec2(p[0], p[1]) / 255.0f;
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        if (!s.normalized) fail(what + " of UNSIGNED_SHORT must be normalized");
        uint16_t v[2];
        std::memcpy(v, p, sizeof v);
        out[i] = glm::vec2(v[0], v[1]) / 65535.0f;
        break;
      }
      default:
        fail(what + " has a componentType glTF does not allow for texture coordinates");
    }
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y)) {
      fail(what + " element " + std::to_string(i) + " is not finite (NaN or Inf)");
    }
  }
  return out;
}

std::vector<uint32_t> GltfAccessors::readIndices(int accessor, std::size_t vertexCount,
                                                 const std::string& what) const {
  const Span s = resolve(accessor, TINYGLTF_TYPE_SCALAR, what);
  std::vector<uint32_t> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    const unsigned char* p = s.data + i * s.stride;
    uint32_t v = 0;
    switch (s.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        v = p[0];
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t u;
        std::memcpy(&u, p, sizeof u);
        v = u;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        std::memcpy(&v, p, sizeof v);
        break;
      default:
        fail(what + " has a componentType glTF does not allow for indices");
    }
    if (v >= vertexCount) {
      fail(what + " index " + std::to_string(v) + " (element " + std::to_string(i) +
           ") is out of range (" + std::to_string(vertexCount) + " vertices)");
    }
    out[i] = v;
  }
  return out;
}

}  // namespace bounce
