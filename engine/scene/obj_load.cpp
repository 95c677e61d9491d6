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

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <string_view>

#include <tbb/parallel_for.h>

#include "io/load_error.h"
#include "io/regular_file.h"
#include "scene/file_name_case.h"
#include "scene/input_limits.h"
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

std::string readText(const std::filesystem::path& path) {
  std::vector<unsigned char> bytes;
  try {
    bytes = readRegularFile(path);
  } catch (const std::runtime_error& e) {
    const std::string message = e.what(), prefix = path.string() + ": ";
    throw LoadError(path, message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message);
  }
  return std::string(bytes.begin(), bytes.end());
}

using NumberKeywords = std::map<std::string_view, std::pair<int, int>>;

// Why `line` is refused (empty when it is not): a control byte, or a statement of `keywords`
// with the wrong count of numbers or one that is not finite or beyond maxAbs.
std::string lineProblem(std::string_view line, const NumberKeywords& keywords, double maxAbs) {
  for (const char c : line) {
    const auto u = static_cast<unsigned char>(c);
    if (u == 0 || (u < 0x20 && c != '\t' && c != '\r'))
      return "binary data (control byte " + std::to_string(u) + "); not a text file";
  }
  std::vector<std::string_view> tokens;
  const std::string_view statement = line.substr(0, line.find('#'));  // a comment ends it
  for (std::size_t i = 0; i < statement.size();) {
    while (i < statement.size() &&
           (statement[i] == ' ' || statement[i] == '\t' || statement[i] == '\r'))
      ++i;
    std::size_t j = i;
    while (j < statement.size() && statement[j] != ' ' && statement[j] != '\t' &&
           statement[j] != '\r')
      ++j;
    if (j > i) tokens.push_back(statement.substr(i, j - i));
    i = j;
  }
  if (tokens.empty()) return {};
  const auto it = keywords.find(tokens[0]);
  if (it == keywords.end()) return {};
  const auto [least, most] = it->second;
  const int count = static_cast<int>(tokens.size()) - 1;
  const std::string keyword(tokens[0]);
  if (count < least || count > most) {
    std::string reason = "'";  // appended, not a + b: g++ 12 warns wrongly on the sum
    reason.append(keyword).append("' takes ").append(std::to_string(least));
    if (least != most) reason.append("-").append(std::to_string(most));
    return reason.append(" numbers, the line has ").append(std::to_string(count));
  }
  for (std::size_t t = 1; t < tokens.size(); ++t) {
    double v = 0.0;
    const char* first = tokens[t].data();
    const char* last = first + tokens[t].size();
    if (*first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last || !std::isfinite(v) || std::abs(v) > maxAbs) {
      std::string reason = "'";
      reason.append(tokens[t]).append("' in '").append(keyword).append("' is not a finite number");
      if (std::isfinite(maxAbs))
        reason.append(" within ±1e6 m, bounce's coordinate limit (docs/input_limits.md)");
      return reason;
    }
  }
  return {};
}

// The lines that begin in text[from, to) (to = text.size() + 1 takes the empty line after a
// last line break too): how many, and the first refused one (its index among them) and why.
struct LinesChecked {
  std::size_t lines = 0;
  std::size_t refused = 0;  // index of the first refused line, when `reason` is not empty
  std::string reason;
};
LinesChecked checkLines(const std::string& text, std::size_t from, std::size_t to,
                        const NumberKeywords& keywords, double maxAbs) {
  LinesChecked checked;
  for (std::size_t begin = from; begin < to; ++checked.lines) {
    std::size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    checked.reason =
        lineProblem(std::string_view(text.data() + begin, end - begin), keywords, maxAbs);
    if (!checked.reason.empty()) {
      checked.refused = checked.lines;
      return checked;
    }
    begin = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
  return checked;
}

// Bytes of text one task checks.
constexpr std::size_t kCheckedPart = std::size_t{1} << 20;

// tinyobjloader reads a number it cannot parse ("nan", "inf", "1e999", "abc") as 0 and a
// missing component as 0: OBJ and MTL statements with numbers are checked here first, so such
// a value is a LoadError naming the line. Binary data (a NUL or other control byte) is refused.
// `keywords` maps a statement to its least and most number of numeric arguments. Lines end as
// tinyobjloader ends them: at "\n", "\r\n" or a lone "\r" (a statement after a lone "\r"
// is one it reads, so it is one checked here). The text is checked in parts of about
// kCheckedPart bytes in parallel, each beginning after a "\n" (where a line begins); the first
// refused line of the first part with one is the file's first, numbered by the lines before it.
void checkNumbers(const std::filesystem::path& path, const std::string& text,
                  const NumberKeywords& keywords, double maxAbs) {
  std::vector<std::size_t> starts{0};
  for (std::size_t at = kCheckedPart; at < text.size(); at = starts.back() + kCheckedPart) {
    const std::size_t lineBreak = text.find('\n', at);
    if (lineBreak == std::string::npos) break;
    starts.push_back(lineBreak + 1);
  }
  std::vector<LinesChecked> parts(starts.size());
  tbb::parallel_for(std::size_t{0}, parts.size(), [&](std::size_t p) {
    const std::size_t to = p + 1 < starts.size() ? starts[p + 1] : text.size() + 1;
    parts[p] = checkLines(text, starts[p], to, keywords, maxAbs);
  });
  std::size_t linesBefore = 0;
  for (const LinesChecked& part : parts) {
    if (!part.reason.empty())
      throw LoadError(
          path, "line " + std::to_string(linesBefore + part.refused + 1) + ": " + part.reason);
    linesBefore += part.lines;
  }
}

// `mtllib` names are resolved in the OBJ's folder and read as regular files only, checked
// before LoadMtl parses them; a missing library is an error, not a warning.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  MaterialLibraries(std::filesystem::path obj) : obj_(std::move(obj)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* materialMap, std::string* warn,
                  std::string* err) override {
    const std::filesystem::path mtl = obj_.parent_path() / name;
    const std::string reason = notRegularFileReason(mtl);
    if (!reason.empty())
      throw LoadError(obj_, "material library '" + name + "' (" + mtl.string() + ") " +
                                (reason == "file not found" ? "not found" : reason));
    std::string text;
    try {  // errors name the OBJ (the file the user gave) and the library
      text = readText(mtl);
      // Kd/Ka/Ks/Ke/Tf: 1 or 3 numbers; Ns, Ni, d, Tr: one.
      checkNumbers(mtl, text,
                   {{"Kd", {1, 3}},
                    {"Ka", {1, 3}},
                    {"Ks", {1, 3}},
                    {"Ke", {1, 3}},
                    {"Tf", {1, 3}},
                    {"Ns", {1, 1}},
                    {"Ni", {1, 1}},
                    {"d", {1, 1}},
                    {"Tr", {1, 1}}},
                   INFINITY);
    } catch (const LoadError& e) {
      throw LoadError(obj_, "material library '" + name + "': " + e.reason());
    }
    std::istringstream in(text);
    tinyobj::LoadMtl(materialMap, materials, &in, warn, err);
    return true;
  }

 private:
  std::filesystem::path obj_;
};

}  // namespace

Scene loadObj(const std::filesystem::path& path) {
  const std::string text = readText(path);
  // v: x y z [w]; vn: 3; vt: 1-3 (u [v [w]]).
  checkNumbers(path, text, {{"v", {3, 4}}, {"vn", {3, 3}}, {"vt", {1, 3}}}, kMaxCoordinate);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning, error;
  std::istringstream in(text);
  MaterialLibraries libraries(path);
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &in, &libraries,
                        /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
    while (!error.empty() && error.back() == '\n') error.pop_back();
    throw LoadError(path, "invalid OBJ: " + (error.empty() ? std::string("parse failed") : error));
  }
  rejectMissingMaterials(path, warning);
  std::size_t faceCount = 0;
  for (const tinyobj::shape_t& shape : shapes) faceCount += shape.mesh.num_face_vertices.size();
  if (faceCount == 0) throw LoadError(path, "no faces (f statements): nothing to render");

  Scene scene;
  const std::filesystem::path folder = path.parent_path();
  std::map<std::string, uint32_t> textureOfFile;
  for (const tinyobj::material_t& m : materials) {
    Material material;
    material.name = m.name;
    material.albedo = glm::clamp(glm::vec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]), 0.0f, 1.0f);
    material.emission = glm::vec3(m.emission[0], m.emission[1], m.emission[2]);  // W/(sr·m²)
    if (!finite(material.albedo) || !finite(material.emission) ||
        glm::any(glm::lessThan(material.emission, glm::vec3(0)))) {
      throw LoadError(path, "material '" + m.name + "' has a negative or non-finite Kd or Ke");
    }
    if (glm::any(
            glm::greaterThan(material.emission, glm::vec3(static_cast<float>(kMaxRadiometric)))))
      throw LoadError(path, "material '" + m.name +
                                "' has Ke beyond bounce's radiance limit of 1e12 W/(sr·m²) "
                                "(docs/input_limits.md)");
    if (!m.diffuse_texname.empty()) {
      auto [it, added] = textureOfFile.try_emplace(m.diffuse_texname, 0);
      if (added) {
        std::filesystem::path image = folder / m.diffuse_texname;
        if (const std::filesystem::path onDisk = findIgnoringCase(folder, m.diffuse_texname);
            !onDisk.empty() && onDisk != image) {
          scene.warnings.push_back(
              path.filename().string() + ": material '" + m.name + "' names its texture '" +
              m.diffuse_texname + "', read as '" +
              std::filesystem::relative(onDisk, folder).string() +
              "' (the name's letter case or separators differ from the file's)");
          image = onDisk;
        }
        scene.textures.push_back(readSrgbTextureFile(path, image));
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

  for (const tinyobj::shape_t& shape : shapes) {
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
    scene.instances.push_back(
        Instance{scene.meshes[m].name, m, glm::mat4(1.0f), Mobility::Static, 1.0f});
  }
  return scene;
}

}  // namespace bounce
