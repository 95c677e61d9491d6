// Wavefront OBJ + MTL → Scene, through tinyobjloader.
//   Kd → albedo ρ; map_Kd → albedo texture (sRGB, decoded to linear); Ke → emission, read as
//   radiance in W/(sr·m²) with no photometric conversion (McGuire's Cornell light: Ke 17 12 4).
//   Lengths are taken as metres: no scale is applied (the conference room is in units of
//   0.003 m; scaling it is the caller's business for now).
// Faces are fan-triangulated. Every triangle gets its own three vertices (no welding), with
// the file's normals when every corner has one, else the flat geometric normal.
// A face whose `usemtl` names a material missing from the .mtl is an error (LoadError naming
// the material), not a silent default: McGuire's CornellBox-Glossy*.obj use `light`, which
// their .mtl lacks, and rendering them without their only emitter would be wrong.
#include <tiny_obj_loader.h>

#include <cmath>
#include <map>
#include <string>

#include "scene/load_error.h"
#include "scene/loaders.h"
#include "scene/texture_decode.h"

namespace bounce {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The quoted name that follows `prefix` in tinyobjloader's warnings, e.g. the light in
// "material [ 'light' ] not found in .mtl"; empty when `prefix` does not occur.
std::string nameAfter(const std::string& warning, const std::string& prefix) {
  const std::size_t at = warning.find(prefix);
  if (at == std::string::npos) return {};
  std::size_t begin = at + prefix.size();
  while (begin < warning.size() && (warning[begin] == ' ' || warning[begin] == '\'')) ++begin;
  std::size_t end = begin;
  while (end < warning.size() && warning[end] != ' ' && warning[end] != '\'') ++end;
  return warning.substr(begin, end - begin);
}

// tinyobjloader reports missing materials and .mtl files as warnings; bounce makes them errors.
void rejectMissingMaterials(const std::filesystem::path& path, const std::string& warning) {
  if (warning.find("] not found") == std::string::npos) return;
  if (const std::string file = nameAfter(warning, "Material file ["); !file.empty()) {
    throw LoadError(path, "material library '" + file + "' not found");
  }
  if (const std::string name = nameAfter(warning, "material ["); !name.empty()) {
    throw LoadError(path,
                    "material '" + name + "' is used (usemtl) but not defined in the .mtl file");
  }
}

}  // namespace

Scene loadObj(const std::filesystem::path& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path.string(), config)) {
    std::string err = reader.Error();
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw LoadError(path, "invalid OBJ: " + (err.empty() ? std::string("parse failed") : err));
  }
  rejectMissingMaterials(path, reader.Warning());

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  Scene scene;
  const std::filesystem::path folder = path.parent_path();
  std::map<std::string, uint32_t> textureOfFile;
  for (const tinyobj::material_t& m : reader.GetMaterials()) {
    Material material;
    material.name = m.name;
    material.albedo = glm::clamp(glm::vec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]), 0.0f, 1.0f);
    material.emission = glm::vec3(m.emission[0], m.emission[1], m.emission[2]);  // W/(sr·m²)
    if (!finite(material.albedo) || !finite(material.emission) ||
        glm::any(glm::lessThan(material.emission, glm::vec3(0)))) {
      throw LoadError(path, "material '" + m.name + "' has a negative or non-finite Kd or Ke");
    }
    if (!m.diffuse_texname.empty()) {
      auto [it, added] = textureOfFile.try_emplace(m.diffuse_texname, 0);
      if (added) {
        scene.textures.push_back(readSrgbTextureFile(path, folder / m.diffuse_texname));
        it->second = static_cast<uint32_t>(scene.textures.size() - 1);
      }
      material.albedoTexture = it->second;
    }
    scene.materials.push_back(std::move(material));
  }
  std::optional<uint32_t> defaultMaterial;  // for faces before any usemtl

  const std::size_t vertexCount = attrib.vertices.size() / 3;
  const std::size_t normalCount = attrib.normals.size() / 3;
  const std::size_t uvCount = attrib.texcoords.size() / 2;
  auto position = [&](const tinyobj::index_t& idx, std::size_t face) {
    if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= vertexCount) {
      throw LoadError(path, "face " + std::to_string(face) + " refers to vertex " +
                                std::to_string(idx.vertex_index + 1) + " of " +
                                std::to_string(vertexCount));
    }
    const auto i = 3 * static_cast<std::size_t>(idx.vertex_index);
    const glm::vec3 p(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);
    if (!finite(p))
      throw LoadError(
          path, "vertex " + std::to_string(idx.vertex_index + 1) + " is not finite (NaN or Inf)");
    return p;
  };

  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const tinyobj::mesh_t& faces = shape.mesh;
    std::map<int, uint32_t> meshOfMaterial;  // this shape's faces split by material
    for (std::size_t f = 0; f < faces.num_face_vertices.size(); ++f) {
      if (faces.num_face_vertices[f] != 3) {
        throw LoadError(
            path, "shape '" + shape.name + "' face " + std::to_string(f) + " was not triangulated");
      }
      const int materialId = f < faces.material_ids.size() ? faces.material_ids[f] : -1;
      auto [it, added] = meshOfMaterial.try_emplace(materialId, 0);
      if (added) {
        Mesh mesh;
        mesh.name = shape.name;
        if (materialId >= 0 && static_cast<std::size_t>(materialId) < scene.materials.size()) {
          mesh.material = static_cast<uint32_t>(materialId);
        } else {
          if (!defaultMaterial) {
            Material material;  // scene.h defaults: albedo 0.8
            material.name = "default";
            scene.materials.push_back(material);
            defaultMaterial = static_cast<uint32_t>(scene.materials.size() - 1);
          }
          mesh.material = *defaultMaterial;
        }
        scene.meshes.push_back(std::move(mesh));
        it->second = static_cast<uint32_t>(scene.meshes.size() - 1);
      }
      Mesh& mesh = scene.meshes[it->second];
      const tinyobj::index_t* corner = &faces.indices[3 * f];
      const glm::vec3 p[3] = {position(corner[0], f), position(corner[1], f),
                              position(corner[2], f)};
      const glm::vec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
      const float len = glm::length(cross);
      const glm::vec3 flat = len > 0.0f ? cross / len : glm::vec3(0, 1, 0);
      bool ownNormals = true;
      for (int c = 0; c < 3; ++c) {
        ownNormals = ownNormals && corner[c].normal_index >= 0 &&
                     static_cast<std::size_t>(corner[c].normal_index) < normalCount;
      }
      for (int c = 0; c < 3; ++c) {
        mesh.indices.push_back(static_cast<uint32_t>(mesh.positions.size()));
        mesh.positions.push_back(p[c]);
        glm::vec3 n = flat;
        if (ownNormals) {
          const auto i = 3 * static_cast<std::size_t>(corner[c].normal_index);
          const glm::vec3 given(attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]);
          const float gl = glm::length(given);
          if (gl > 0.0f && std::isfinite(gl)) n = given / gl;
        }
        mesh.normals.push_back(n);
        glm::vec2 uv(0.0f);
        const int t = corner[c].texcoord_index;
        if (t >= 0 && static_cast<std::size_t>(t) < uvCount) {
          const auto i = 2 * static_cast<std::size_t>(t);
          uv = glm::vec2(attrib.texcoords[i], 1.0f - attrib.texcoords[i + 1]);  // OBJ v is up
        }
        mesh.uv0.push_back(uv);
      }
    }
  }
  for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
    scene.instances.push_back(Instance{scene.meshes[m].name, m, glm::mat4(1.0f), Mobility::Static});
  }
  return scene;
}

}  // namespace bounce
