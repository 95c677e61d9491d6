// glTF 2.0 → Scene. tinygltf parses the JSON, the buffers and the images; everything it does
// not check (indices, byte ranges, finiteness, extensions, light and camera values) is checked
// here, so a bad file is one LoadError and never a crash.
#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "io/load_error.h"
#include "io/regular_file.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_schema.h"
#include "scene/input_limits.h"
#include "scene/loaders.h"
#include "scene/mesh_normals.h"
#include "scene/texture_decode.h"
#include "scene/units.h"

namespace bounce {
namespace {

// Extensions bounce understands; any other in extensionsRequired makes the file unloadable.
// Others in extensionsUsed are optional by definition and ignored (glTF 2.0 §3.12).
constexpr std::array kSupportedExtensions = {"KHR_lights_punctual",
                                             "KHR_materials_emissive_strength"};

std::vector<unsigned char> readBytes(const std::filesystem::path& path) {
  try {
    return readRegularFile(path);
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    const std::string prefix = path.string() + ": ";
    throw LoadError(path, message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message);
  }
}

// tinygltf reads the buffers and images a file names through these: regular files only (a
// FIFO or a device named by a `uri` would block or stream forever), no shell expansion of the
// name, never a write.
bool regularFileExists(const std::string& path, void*) {
  return notRegularFileReason(path) != "file not found";
}
std::string unexpandedPath(const std::string& path, void*) {
  return path;
}
bool readReferencedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                        void*) {
  try {
    *out = readRegularFile(path);
    return true;
  } catch (const std::exception& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}
bool refuseWrite(std::string* err, const std::string& path, const std::vector<unsigned char>&,
                 void*) {
  if (err) *err += path + ": bounce never writes while loading\n";
  return false;
}

// tinygltf's image decoder behind a size check on the image header: a texture beyond the
// limits (input_limits.h) is refused before width × height texels are allocated.
bool decodeImageWithinLimits(tinygltf::Image* image, const int index, std::string* err,
                             std::string* warn, int reqWidth, int reqHeight,
                             const unsigned char* bytes, int size, void* user) {
  int width = 0, height = 0, components = 0;
  if (stbi_info_from_memory(bytes, size, &width, &height, &components) != 0) {
    if (const std::string problem = textureSizeProblem(width, height); !problem.empty()) {
      if (err)
        *err += "image " + std::to_string(index) + " '" + image->uri + "': " + problem + "\n";
      return false;
    }
  }
  return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size, user);
}

uint32_t readU32(const std::vector<unsigned char>& bytes, std::size_t offset) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + offset, sizeof v);
  return v;
}

// The GLB container (header, JSON chunk, optional BIN chunk) must be complete before tinygltf
// sees it: a truncated .glb is reported here, with the sizes.
void checkGlbContainer(const std::filesystem::path& path, const std::vector<unsigned char>& b) {
  const std::size_t size = b.size();
  if (size < 20)
    throw LoadError(path, "truncated GLB: " + std::to_string(size) + " bytes, no header");
  if (std::memcmp(b.data(), "glTF", 4) != 0) throw LoadError(path, "not a GLB file (bad magic)");
  if (readU32(b, 4) != 2)
    throw LoadError(path, "GLB version " + std::to_string(readU32(b, 4)) + " (expected 2)");
  const std::size_t declared = readU32(b, 8);
  if (declared != size) {
    throw LoadError(path, "truncated or padded GLB: header declares " + std::to_string(declared) +
                              " bytes, the file has " + std::to_string(size));
  }
  const std::size_t jsonLength = readU32(b, 12);
  if (std::memcmp(b.data() + 16, "JSON", 4) != 0)
    throw LoadError(path, "GLB's first chunk is not JSON");
  if (jsonLength > size - 20) throw LoadError(path, "truncated GLB: JSON chunk exceeds the file");
  const std::size_t binStart = 20 + jsonLength;
  if (binStart == size) return;
  if (size - binStart < 8) throw LoadError(path, "truncated GLB: incomplete BIN chunk header");
  const std::size_t binLength = readU32(b, binStart);
  if (binLength > size - binStart - 8)
    throw LoadError(path, "truncated GLB: BIN chunk exceeds the file");
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  std::replace(s.begin(), s.end(), '\n', ';');
  return s;
}

glm::mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));  // column-major
    return glm::mat4(m);
  }
  glm::dmat4 t(1.0), r(1.0), s(1.0);
  if (node.translation.size() == 3) {
    t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (node.rotation.size() == 4) {  // glTF order x, y, z, w
    r = glm::mat4_cast(glm::normalize(
        glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])));
  }
  if (node.scale.size() == 3)
    s = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return glm::mat4(t * r * s);  // T·R·S (glTF 2.0 §3.5.3)
}

// A camera node's world matrix without its scale and shear: the view direction (−Z) and the
// up axis (+Y, made orthogonal to it) are kept, +X = Y × Z, so the result is a rotation plus
// the node's translation — the right-handed glTF camera frame even under a mirroring parent.
// The renderer's view matrix is its inverse: with scale left in, that inverse would rescale the
// clip range znear..zfar (metres). Empty when the columns are zero or linearly dependent.
std::optional<glm::mat4> rigidFrame(const glm::mat4& m) {
  const glm::dvec3 x(m[0]), y(m[1]), z(m[2]);
  const double det = glm::dot(x, glm::cross(y, z));
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
  const glm::dvec3 ez = glm::normalize(z);
  const glm::dvec3 yPerp = y - glm::dot(y, ez) * ez;
  if (!(glm::length(yPerp) > 0.0)) return std::nullopt;
  const glm::dvec3 ey = glm::normalize(yPerp);
  const glm::dvec3 ex = glm::cross(ey, ez);
  glm::mat4 rigid(1.0f);
  rigid[0] = glm::vec4(glm::vec3(ex), 0.0f);
  rigid[1] = glm::vec4(glm::vec3(ey), 0.0f);
  rigid[2] = glm::vec4(glm::vec3(ez), 0.0f);
  rigid[3] = glm::vec4(glm::vec3(m[3]), 1.0f);
  return rigid;
}

// A number for messages: 6 significant digits, exponent form for large values ("1.46413e+39").
std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

std::string coordinateLimitText() {
  return "beyond bounce's coordinate limit of 1e6 m (docs/input_limits.md)";
}

bool allFinite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

class GltfBuilder {
 public:
  GltfBuilder(const tinygltf::Model& model, const std::filesystem::path& path)
      : model_(model), path_(path), accessors_(model, path) {}

  Scene build() {
    checkExtensions();
    for (std::size_t i = 0; i < model_.materials.size(); ++i) addMaterial(i);
    for (std::size_t i = 0; i < model_.meshes.size(); ++i) addMesh(i);
    addNodes();
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const { throw LoadError(path_, reason); }

  void checkExtensions() const {
    for (const std::string& ext : model_.extensionsRequired) {
      if (std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), ext) ==
          kSupportedExtensions.end()) {
        fail("requires the unsupported extension '" + ext + "' (extensionsRequired)");
      }
    }
  }

  template <typename T>
  void checkIndex(int index, const std::vector<T>& items, const std::string& what) const {
    if (index < 0 || static_cast<std::size_t>(index) >= items.size()) {
      fail(what + " index " + std::to_string(index) + " is out of range (the file has " +
           std::to_string(items.size()) + ")");
    }
  }

  // `v` as a float; a value finite in double but beyond float's range (~3.4e38) is an error,
  // not a silent infinity.
  float toFloat(double v, const std::string& what) const {
    const auto f = static_cast<float>(v);
    if (!std::isfinite(f)) fail(what + " (" + std::to_string(v) + ") is not representable");
    return f;
  }

  // A radiometric value (after the photometric conversion) within kMaxRadiometric.
  float radiometricValue(double v, const std::string& what) const {
    if (!(v <= kMaxRadiometric)) {
      fail(what + " " + shortNumber(v) + " exceeds bounce's limit of 1e12 (docs/input_limits.md)");
    }
    return toFloat(v, what);
  }

  glm::vec3 vec3(const std::vector<double>& v, glm::dvec3 fallback, const std::string& what) const {
    if (v.empty()) return glm::vec3(fallback);
    if (v.size() < 3) fail(what + " has fewer than 3 components");
    for (std::size_t i = 0; i < 3; ++i)
      if (!std::isfinite(v[i]) || v[i] < 0.0) fail(what + " is negative or not finite");
    return glm::vec3(v[0], v[1], v[2]);
  }

  void addMaterial(std::size_t index) {
    const tinygltf::Material& m = model_.materials[index];
    const std::string what = "material " + std::to_string(index) + " '" + m.name + "'";
    Material material;
    material.name = m.name.empty() ? "material" + std::to_string(index) : m.name;
    material.albedo =
        vec3(m.pbrMetallicRoughness.baseColorFactor, glm::dvec3(1.0), what + " baseColorFactor");
    material.albedo = glm::min(material.albedo, glm::vec3(1.0f));
    const tinygltf::TextureInfo& base = m.pbrMetallicRoughness.baseColorTexture;
    if (base.index >= 0) {
      if (base.texCoord != 0)
        fail(what + ": baseColorTexture uses TEXCOORD_" + std::to_string(base.texCoord) +
             " (bounce reads it through TEXCOORD_0)");
      material.albedoTexture = texture(base.index, what);
    }
    // Emission: emissiveFactor × KHR_materials_emissive_strength is a luminance in cd/m²,
    // converted per channel in double (units.h).
    double strength = 1.0;
    if (auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
      const tinygltf::Value& s = it->second.Get("emissiveStrength");
      if (s.IsNumber()) strength = s.GetNumberAsDouble();
      if (!std::isfinite(strength) || strength < 0.0)
        fail(what + ": emissiveStrength is negative or not finite");
    }
    const glm::dvec3 factor(vec3(m.emissiveFactor, glm::dvec3(0.0), what + " emissiveFactor"));
    if (!m.emissiveFactor.empty()) {  // keep the exact doubles of the file
      const glm::dvec3 exact(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
      for (int c = 0; c < 3; ++c)
        material.emission[c] = radiometricValue(nitsToRadiance(exact[c] * strength),
                                                what + ": emitted radiance W/(sr·m²)");
    } else {
      material.emission = glm::vec3(factor);
    }
    material.doubleSided = m.doubleSided;
    // extras.bounce.bake: "all" bakes an emitter's direct light too (scene.h,
    // Material::bakeDirect).
    if (m.extras.Has("bounce") && m.extras.Get("bounce").Has("bake")) {
      const tinygltf::Value& bake = m.extras.Get("bounce").Get("bake");
      const std::string mode = bake.IsString() ? bake.Get<std::string>() : "";
      if (mode != "all" && mode != "indirect")
        fail(what + ": material extras.bounce.bake must be \"all\" or \"indirect\"");
      material.bakeDirect = mode == "all";
    }
    warnIgnored(m, material.name);
    scene_.materials.push_back(std::move(material));
  }

  // Features that change what the file looks like but that the scene model cannot hold
  // (docs/units.md): loaded without them, with a warning in Scene::warnings.
  void warnIgnored(const tinygltf::Material& m, const std::string& name) {
    const std::string what = "material '" + name + "'";
    if (m.emissiveTexture.index >= 0)
      scene_.warnings.push_back(what + ": emissiveTexture ignored (emission is uniform)");
    if (m.pbrMetallicRoughness.baseColorTexture.extensions.count("KHR_texture_transform") != 0)
      scene_.warnings.push_back(what + ": KHR_texture_transform on baseColorTexture ignored");
  }

  uint32_t texture(int textureIndex, const std::string& what) {
    checkIndex(textureIndex, model_.textures, what + " texture");
    const int source = model_.textures[static_cast<std::size_t>(textureIndex)].source;
    checkIndex(source, model_.images, what + " image");
    if (auto it = textureOfImage_.find(source); it != textureOfImage_.end()) return it->second;
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(source)];
    const std::string imageName =
        image.uri.empty() ? "image " + std::to_string(source) : "'" + image.uri + "'";
    if (image.image.empty()) fail(what + ": " + imageName + " could not be decoded");
    try {
      scene_.textures.push_back(decodeSrgbTexture(image.name.empty() ? image.uri : image.name,
                                                  image.width, image.height, image.component,
                                                  image.bits, image.image));
    } catch (const std::invalid_argument& e) {
      fail(what + ": " + imageName + ": " + e.what());
    }
    const auto index = static_cast<uint32_t>(scene_.textures.size() - 1);
    textureOfImage_[source] = index;
    return index;
  }

  uint32_t defaultMaterial() {
    if (!defaultMaterial_) {
      Material material;  // scene.h defaults: albedo 0.8, no emission
      material.name = "default";
      scene_.materials.push_back(material);
      defaultMaterial_ = static_cast<uint32_t>(scene_.materials.size() - 1);
    }
    return *defaultMaterial_;
  }

  void addMesh(std::size_t meshIndex) {
    const tinygltf::Mesh& gm = model_.meshes[meshIndex];
    std::vector<uint32_t> ours;
    for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = gm.primitives[p];
      const std::string what =
          "mesh " + std::to_string(meshIndex) + " '" + gm.name + "' primitive " + std::to_string(p);
      if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES) {
        fail(what + " has mode " + std::to_string(prim.mode) +
             "; bounce loads triangles (mode 4) only");
      }
      Mesh mesh;
      mesh.name = gm.primitives.size() > 1 ? gm.name + "#" + std::to_string(p) : gm.name;
      auto attribute = [&](const char* name) {
        auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
      };
      const int position = attribute("POSITION");
      if (position < 0) fail(what + " has no POSITION");
      mesh.positions = accessors_.readVec3(position, what + " POSITION");
      for (const glm::vec3& q : mesh.positions)
        if (!withinCoordinateLimit(glm::dvec3(q)))
          fail(what + " POSITION is " + coordinateLimitText());
      const std::size_t n = mesh.positions.size();
      if (const int a = attribute("NORMAL"); a >= 0)
        mesh.normals = accessors_.readVec3(a, what + " NORMAL");
      if (const int a = attribute("TEXCOORD_0"); a >= 0)
        mesh.uv0 = accessors_.readVec2(a, what + " TEXCOORD_0");
      if (const int a = attribute("TEXCOORD_1"); a >= 0)
        mesh.uv1 = accessors_.readVec2(a, what + " TEXCOORD_1");
      if ((!mesh.normals.empty() && mesh.normals.size() != n) ||
          (!mesh.uv0.empty() && mesh.uv0.size() != n) ||
          (!mesh.uv1.empty() && mesh.uv1.size() != n)) {
        fail(what + ": attribute counts differ from POSITION's " + std::to_string(n));
      }
      if (prim.indices >= 0) {
        mesh.indices = accessors_.readIndices(prim.indices, n, what + " indices");
      } else {
        mesh.indices.resize(n);
        for (std::size_t i = 0; i < n; ++i) mesh.indices[i] = static_cast<uint32_t>(i);
      }
      if (mesh.indices.size() % 3 != 0)
        fail(what + ": index count " + std::to_string(mesh.indices.size()) +
             " is not a multiple of 3");
      repairNormals(mesh);  // zero or non-finite NORMAL entries: from the adjacent triangles
      if (mesh.normals.empty()) makeFlatNormals(mesh);  // glTF 2.0 §3.7.2.1: flat when absent
      if (prim.material >= 0) {
        checkIndex(prim.material, model_.materials, what + " material");
        mesh.material = static_cast<uint32_t>(prim.material);
      } else {
        mesh.material = defaultMaterial();
      }
      scene_.meshes.push_back(std::move(mesh));
      ours.push_back(static_cast<uint32_t>(scene_.meshes.size() - 1));
    }
    meshesOf_.push_back(std::move(ours));
  }

  // Every vertex of `mesh` placed by `world`, in double: within kMaxCoordinate (the renderer and
  // the tracer square and subtract world coordinates in float).
  void checkWorldCoordinates(const Mesh& mesh, const glm::mat4& world, const std::string& what) {
    const glm::dmat4 m(world);
    for (const glm::vec3& p : mesh.positions) {
      if (!withinCoordinateLimit(glm::dvec3(m * glm::dvec4(glm::dvec3(p), 1.0))))
        fail(what + ": mesh '" + mesh.name + "' has a world coordinate " + coordinateLimitText());
    }
  }

  Mobility mobility(const tinygltf::Node& node, Mobility inherited, const std::string& what) const {
    if (!node.extras.Has("bounce")) return inherited;
    const tinygltf::Value& bounce = node.extras.Get("bounce");
    if (!bounce.Has("mobility")) return inherited;
    const tinygltf::Value& value = bounce.Get("mobility");
    const std::string s = value.IsString() ? value.Get<std::string>() : "";
    if (s == "static") return Mobility::Static;
    if (s == "dynamic") return Mobility::Dynamic;
    fail(what + ": extras.bounce.mobility must be \"static\" or \"dynamic\"");
  }

  // extras.bounce.lightmapScale of a node, else its parent's: a number in [0, kMaxLightmapScale]
  // (0: no lightmap, baked light from irradiance probes).
  float lightmapScale(const tinygltf::Node& node, float inherited, const std::string& what) const {
    if (!node.extras.Has("bounce")) return inherited;
    const tinygltf::Value& bounce = node.extras.Get("bounce");
    if (!bounce.Has("lightmapScale")) return inherited;
    const tinygltf::Value& value = bounce.Get("lightmapScale");
    const double scale = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
    if (!(scale >= 0.0 && scale <= kMaxLightmapScale))
      fail(what + ": extras.bounce.lightmapScale must be a number in [0, " +
           std::to_string(static_cast<int>(kMaxLightmapScale)) +
           "] (texels per metre relative to the scene's; 0: no lightmap, light from probes)");
    return static_cast<float>(scale);
  }

  void addLight(int index, const glm::mat4& world, Mobility mobility, const std::string& what) {
    checkIndex(index, model_.lights, what + " KHR_lights_punctual light");
    const tinygltf::Light& gl = model_.lights[static_cast<std::size_t>(index)];
    Light light;
    light.name = gl.name.empty() ? "light" + std::to_string(index) : gl.name;
    vec3(gl.color, glm::dvec3(1.0), what + " light color");  // checks: 3 finite, non-negative
    const glm::dvec3 color =  // the file's exact doubles: color × intensity may exceed float
        gl.color.empty() ? glm::dvec3(1.0) : glm::dvec3(gl.color[0], gl.color[1], gl.color[2]);
    if (!std::isfinite(gl.intensity) || gl.intensity < 0.0)
      fail(what + ": light intensity is negative or not finite");
    if (!withinCoordinateLimit(glm::dvec3(world[3])))
      fail(what + ": light position is " + coordinateLimitText());
    light.position = glm::vec3(world[3]);
    // Lights shine along −Z; in double, so a large scale cannot overflow the length.
    const glm::dvec3 down = -glm::dvec3(world[2]);
    const double length = glm::length(down);
    if (!(length > 0.0) || !std::isfinite(length))
      fail(what + ": the light's transform is degenerate");
    light.direction = glm::vec3(down / length);
    glm::vec3 radiometric;
    if (gl.type == "directional") {
      light.type = LightType::Directional;
      for (int c = 0; c < 3; ++c)
        radiometric[c] = radiometricValue(luxToWattsPerM2(color[c] * gl.intensity),
                                          what + ": light irradiance W/m²");
      light.irradiance = radiometric;
    } else if (gl.type == "point" || gl.type == "spot") {
      light.type = gl.type == "point" ? LightType::Point : LightType::Spot;
      for (int c = 0; c < 3; ++c)
        radiometric[c] = radiometricValue(candelaToWattsPerSr(color[c] * gl.intensity),
                                          what + ": light intensity W/sr");
      light.intensity = radiometric;
      if (light.type == LightType::Spot) {
        const double inner = gl.spot.innerConeAngle, outer = gl.spot.outerConeAngle;
        if (!(inner >= 0.0 && inner < outer && outer <= 1.5707963267948966)) {
          fail(what + ": spot cone angles need 0 <= inner < outer <= pi/2");
        }
        light.innerConeAngle = static_cast<float>(inner);
        light.outerConeAngle = static_cast<float>(outer);
      }
    } else {
      fail(what + ": unknown light type '" + gl.type + "'");
    }
    // extras.bounce.bake: "all" bakes the light's direct light too (scene.h, Light::bakeDirect).
    if (gl.extras.Has("bounce") && gl.extras.Get("bounce").Has("bake")) {
      const tinygltf::Value& bake = gl.extras.Get("bounce").Get("bake");
      const std::string mode = bake.IsString() ? bake.Get<std::string>() : "";
      if (mode != "all" && mode != "indirect")
        fail(what + ": light extras.bounce.bake must be \"all\" or \"indirect\"");
      light.bakeDirect = mode == "all";
    }
    light.mobility = mobility;
    scene_.lights.push_back(light);
  }

  void addCamera(int index, const glm::mat4& world, const tinygltf::Node& node,
                 const std::string& what) {
    checkIndex(index, model_.cameras, what + " camera");
    const tinygltf::Camera& gc = model_.cameras[static_cast<std::size_t>(index)];
    if (gc.type != "perspective")
      fail(what + ": camera type '" + gc.type + "' is not supported (perspective only)");
    const tinygltf::PerspectiveCamera& p = gc.perspective;
    if (!(p.yfov > 0.0 && p.yfov < 3.14159) || !(p.znear > 0.0) || p.aspectRatio < 0.0 ||
        p.zfar < 0.0 || !std::isfinite(p.aspectRatio) || !std::isfinite(p.zfar)) {
      fail(what + ": perspective camera needs 0 < yfov < pi, znear > 0, aspectRatio and zfar >= 0");
    }
    Camera camera;
    camera.name = !gc.name.empty()     ? gc.name
                  : !node.name.empty() ? node.name
                                       : "camera" + std::to_string(index);
    const std::optional<glm::mat4> rigid = rigidFrame(world);
    if (!rigid)
      fail(what + ": camera '" + camera.name + "' has a degenerate transform (zero scale)");
    if (!withinCoordinateLimit(glm::dvec3(world[3])))
      fail(what + ": camera position is " + coordinateLimitText());
    if (p.znear < kMinZnear)
      fail(what + ": camera znear " + shortNumber(p.znear) +
           " m is below bounce's limit of 1e-6 m (docs/input_limits.md)");
    camera.cameraToWorld = *rigid;
    camera.yfov = static_cast<float>(p.yfov);
    camera.aspect = toFloat(p.aspectRatio, what + ": camera aspectRatio");
    camera.znear = toFloat(p.znear, what + ": camera znear");
    // zfar 0/absent means infinite: a finite default that stays beyond znear (a projection
    // with znear >= zfar is empty).
    camera.zfar = p.zfar > p.znear ? toFloat(p.zfar, what + ": camera zfar")
                                   : std::max(1000.0f, 2.0f * camera.znear);
    scene_.cameras.push_back(camera);
  }

  // Walks the default scene's node trees (explicit stack: deep files cannot overflow it),
  // composing world = parent · local, and places meshes, lights and cameras.
  void addNodes() {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      checkIndex(s, model_.scenes, "default scene");
      roots = model_.scenes[static_cast<std::size_t>(s)].nodes;
    } else {  // no scene at all: show every root node rather than nothing
      std::vector<bool> isChild(model_.nodes.size(), false);
      for (const tinygltf::Node& node : model_.nodes)
        for (const int c : node.children)
          if (c >= 0 && static_cast<std::size_t>(c) < isChild.size())
            isChild[static_cast<std::size_t>(c)] = true;
      for (std::size_t n = 0; n < model_.nodes.size(); ++n)
        if (!isChild[n]) roots.push_back(static_cast<int>(n));
    }
    struct Pending {
      int node;
      glm::mat4 parent;
      Mobility mobility;
      float lightmapScale;
    };
    std::vector<Pending> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
      stack.push_back({*it, glm::mat4(1.0f), Mobility::Static, 1.0f});
    std::vector<bool> visited(model_.nodes.size(), false);
    while (!stack.empty()) {
      const Pending item = stack.back();
      stack.pop_back();
      checkIndex(item.node, model_.nodes, "node");
      const auto n = static_cast<std::size_t>(item.node);
      const std::string what = "node " + std::to_string(n) + " '" + model_.nodes[n].name + "'";
      if (visited[n]) fail(what + " is reached twice (node hierarchies must be trees)");
      visited[n] = true;
      const tinygltf::Node& node = model_.nodes[n];
      if (!node.matrix.empty() && node.matrix.size() != 16)
        fail(what + ": matrix needs 16 numbers");
      const glm::mat4 world = item.parent * localTransform(node);
      if (!allFinite(world)) fail(what + ": transform is not finite");
      const Mobility mob = mobility(node, item.mobility, what);
      const float scale = lightmapScale(node, item.lightmapScale, what);
      if (node.mesh >= 0) {
        checkIndex(node.mesh, model_.meshes, what + " mesh");
        for (const uint32_t mesh : meshesOf_[static_cast<std::size_t>(node.mesh)]) {
          checkWorldCoordinates(scene_.meshes[mesh], world, what);
          scene_.instances.push_back(Instance{
              node.name.empty() ? scene_.meshes[mesh].name : node.name, mesh, world, mob, scale});
        }
      } else if (node.mesh < -1) {
        fail(what + ": mesh index " + std::to_string(node.mesh) + " is out of range");
      }
      if (node.camera >= 0 || node.camera < -1) addCamera(node.camera, world, node, what);
      if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end()) {
        const tinygltf::Value& light = it->second.Get("light");
        if (!light.IsInt()) fail(what + ": KHR_lights_punctual.light is not an index");
        addLight(light.Get<int>(), world, mob, what);
      }
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
        stack.push_back({*c, world, mob, scale});
    }
  }

  const tinygltf::Model& model_;
  std::filesystem::path path_;
  GltfAccessors accessors_;
  Scene scene_;
  std::vector<std::vector<uint32_t>> meshesOf_;  // glTF mesh → our meshes (one per primitive)
  std::map<int, uint32_t> textureOfImage_;
  std::optional<uint32_t> defaultMaterial_;
};

}  // namespace

Scene loadGltf(const std::filesystem::path& path) {
  const std::vector<unsigned char> bytes = readBytes(path);
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (binary || path.extension() == ".glb") checkGlbContainer(path, bytes);
  // The JSON (all of a .gltf, the first chunk of a .glb): depth and types, before tinygltf.
  const std::string_view json =
      binary
          ? std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20, readU32(bytes, 12))
          : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  checkGltfSchema(path, json);
  tinygltf::TinyGLTF parser;
  parser.SetFsCallbacks(tinygltf::FsCallbacks{&regularFileExists, &unexpandedPath,
                                              &readReferencedFile, &refuseWrite, nullptr});
  parser.SetImageLoader(&decodeImageWithinLimits, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const std::string baseDir = path.parent_path().string();
  const bool ok =
      binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                           static_cast<unsigned int>(bytes.size()), baseDir)
             : parser.LoadASCIIFromString(&model, &err, &warn,
                                          reinterpret_cast<const char*>(bytes.data()),
                                          static_cast<unsigned int>(bytes.size()), baseDir);
  if (!ok) throw LoadError(path, "invalid glTF: " + trimmed(err.empty() ? warn : err));
  return GltfBuilder(model, path).build();
}

}  // namespace bounce
