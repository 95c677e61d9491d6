// A scene wrapper (.json): one model file by path (never copied), uniformly scaled into metres,
// plus punctual lights and a camera in metres and radians. Used for models kept outside the
// repository in their own units (the conference room is modelled in 3 mm units).
//
//   {
//     "model": "relative/or/absolute/path.obj",    (.obj, .gltf or .glb; relative to this file)
//     "scale": 0.003,                              (metres per model unit, > 0; default 1)
//     "lights": [{"type": "spot" | "point" | "directional", "name": "...",
//                 "position": [x, y, z],           (metres; point, spot)
//                 "direction": [x, y, z],          (the way light travels; spot, directional)
//                 "intensity": [r, g, b],          (W/sr; point, spot)
//                 "irradiance": [r, g, b],         (W/m²; directional)
//                 "inner_cone": a, "outer_cone": b,  (radians; spot)
//                 "mobility": "static" | "dynamic"}],  (default static; scene.h Light::mobility)
//     "emitters": [{"name": "...", "radiance": [r, g, b],     (W/(sr·m²), emitted by the front)
//                   "albedo": [r, g, b], "double_sided": false,  (default 0.8, false)
//                   "bake": "indirect" | "all",  ("all": its direct light is baked too)
//                   "quads": [{"corner": [x, y, z], "u": [..], "v": [..]}, ...]}],
//                                   (metres, not scaled: corner, corner+u, corner+u+v, corner+v,
//                                    front face u × v; all quads of one entry are one mesh, as
//                                    exporters write a fixture's panels)
//     "camera": {"position": [..], "target": [..], "yfov": 0.9, "znear": 0.05, "zfar": 100}
//   }
// Lights, emitters and the camera are added to (the camera before) those of the model.
#include <cmath>
#include <sstream>
#include <string_view>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "io/json_depth.h"
#include "io/regular_file.h"
#include "scene/input_limits.h"
#include "scene/load.h"
#include "scene/loaders.h"

namespace bounce {
namespace {

using nlohmann::json;

glm::vec3 vec3Of(const std::filesystem::path& path, const json& value, const std::string& what) {
  if (!value.is_array() || value.size() != 3)
    throw LoadError(path, "'" + what + "' must be an array of 3 numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!value[static_cast<std::size_t>(i)].is_number())
      throw LoadError(path, "'" + what + "' must be an array of 3 numbers");
    v[i] = value[static_cast<std::size_t>(i)].get<float>();
    if (!std::isfinite(v[i])) throw LoadError(path, "'" + what + "' is not finite");
  }
  return v;
}

float numberOf(const std::filesystem::path& path, const json& object, const std::string& key,
               float fallback) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_number()) throw LoadError(path, "'" + key + "' must be a number");
  const float v = object[key].get<float>();
  if (!std::isfinite(v)) throw LoadError(path, "'" + key + "' is not finite");
  return v;
}

Light lightOf(const std::filesystem::path& path, const json& entry) {
  if (!entry.is_object() || !entry.contains("type") || !entry["type"].is_string())
    throw LoadError(path, "each light needs a \"type\" (point, spot or directional)");
  Light light;
  const std::string type = entry["type"].get<std::string>();
  light.name = entry.value("name", type);
  if (type == "point" || type == "spot") {
    light.type = type == "point" ? LightType::Point : LightType::Spot;
    light.position = vec3Of(path, entry.value("position", json()), "position");
    light.intensity = vec3Of(path, entry.value("intensity", json()), "intensity");
  } else if (type == "directional") {
    light.type = LightType::Directional;
    light.irradiance = vec3Of(path, entry.value("irradiance", json()), "irradiance");
  } else {
    throw LoadError(path, "unknown light type '" + type + "'");
  }
  if (light.type != LightType::Point) {
    const glm::vec3 d = vec3Of(path, entry.value("direction", json()), "direction");
    if (!(glm::length(d) > 0.0f)) throw LoadError(path, "light direction has zero length");
    light.direction = glm::normalize(d);
  }
  light.innerConeAngle = numberOf(path, entry, "inner_cone", light.innerConeAngle);
  light.outerConeAngle = numberOf(path, entry, "outer_cone", light.outerConeAngle);
  if (entry.contains("mobility")) {
    const json& mobility = entry["mobility"];
    const std::string value = mobility.is_string() ? mobility.get<std::string>() : "";
    if (value != "static" && value != "dynamic")
      throw LoadError(path,
                      "light '" + light.name + "': \"mobility\" must be \"static\" or \"dynamic\"");
    light.mobility = value == "dynamic" ? Mobility::Dynamic : Mobility::Static;
  }
  return light;
}

// A wrapper is a few lines; anything larger is not one.
constexpr std::size_t kMaxWrapperBytes = std::size_t{1} << 20;

bool withinRadiometricLimit(glm::vec3 v) {
  for (int i = 0; i < 3; ++i)
    if (!(v[i] >= 0.0f && v[i] <= kMaxRadiometric)) return false;
  return true;
}

// One emitter entry as one static instance of one mesh of quads and its emissive material.
void addEmitter(const std::filesystem::path& path, const json& entry, Scene& scene) {
  if (!entry.is_object() || !entry.contains("quads") || !entry["quads"].is_array() ||
      entry["quads"].empty())
    throw LoadError(path, "each emitter needs \"quads\": a non-empty array");
  Material material;
  material.name = entry.value("name", std::string("emitter"));
  material.emission = vec3Of(path, entry.value("radiance", json()), "radiance");
  if (entry.contains("albedo")) material.albedo = vec3Of(path, entry["albedo"], "albedo");
  if (entry.contains("bake")) {
    const json& bake = entry["bake"];
    if (!bake.is_string() || (bake != "all" && bake != "indirect"))
      throw LoadError(path,
                      "emitter '" + material.name + "': 'bake' must be \"all\" or \"indirect\"");
    material.bakeDirect = bake == "all";
  }
  if (entry.contains("double_sided")) {
    if (!entry["double_sided"].is_boolean())
      throw LoadError(path, "'double_sided' must be true or false");
    material.doubleSided = entry["double_sided"].get<bool>();
  }
  if (!withinRadiometricLimit(material.emission) || !withinRadiometricLimit(material.albedo))
    throw LoadError(path, "emitter '" + material.name +
                              "' has a negative radiance or albedo, or one beyond " +
                              std::to_string(kMaxRadiometric));
  Mesh mesh;
  mesh.name = material.name;
  mesh.material = static_cast<uint32_t>(scene.materials.size());
  for (const json& quad : entry["quads"]) {
    if (!quad.is_object()) throw LoadError(path, "each quad needs corner, u and v");
    const glm::vec3 c = vec3Of(path, quad.value("corner", json()), "corner");
    const glm::vec3 u = vec3Of(path, quad.value("u", json()), "u");
    const glm::vec3 v = vec3Of(path, quad.value("v", json()), "v");
    const glm::vec3 n = glm::cross(u, v);
    if (!(glm::length(n) > 0.0f))
      throw LoadError(path, "emitter '" + material.name + "' has a quad of zero area");
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (const glm::vec3& p : {c, c + u, c + u + v, c + v}) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(glm::normalize(n));
    }
    for (const uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  }
  Instance instance;
  instance.name = material.name;
  instance.mesh = static_cast<uint32_t>(scene.meshes.size());
  scene.materials.push_back(std::move(material));
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back(std::move(instance));
}

// The same limits the model's own loader applied (docs/input_limits.md), now to what the wrapper
// made of it: its scale moves every vertex, light and camera, and it adds lights and a camera.
void checkLimits(const std::filesystem::path& path, const Scene& scene) {
  const std::string beyond = "beyond bounce's limit of " + std::to_string(kMaxCoordinate) + " m";
  for (const Instance& instance : scene.instances) {
    const glm::dmat4 world(instance.transform);
    for (const glm::vec3& p : scene.meshes.at(instance.mesh).positions)
      if (!withinCoordinateLimit(glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0))))
        throw LoadError(path, "instance '" + instance.name + "' has a vertex " + beyond +
                                  " after the wrapper's scale");
  }
  for (const Light& light : scene.lights) {
    if (!withinCoordinateLimit(glm::dvec3(light.position)))
      throw LoadError(path, "light '" + light.name + "' is placed " + beyond);
    if (!withinRadiometricLimit(light.intensity) || !withinRadiometricLimit(light.irradiance))
      throw LoadError(path, "light '" + light.name +
                                "' has a negative intensity/irradiance or one beyond " +
                                std::to_string(kMaxRadiometric) + " W/sr (W/m²)");
  }
  for (const Camera& camera : scene.cameras) {
    if (!withinCoordinateLimit(glm::dvec3(camera.position())))
      throw LoadError(path, "camera '" + camera.name + "' is placed " + beyond);
    if (!(camera.znear >= kMinZnear))
      throw LoadError(
          path, "camera '" + camera.name + "' has znear below " + std::to_string(kMinZnear) + " m");
  }
}

}  // namespace

Scene loadSceneJson(const std::filesystem::path& path) {
  std::vector<unsigned char> bytes;
  try {
    bytes = readRegularFile(path, kMaxWrapperBytes);
  } catch (const std::runtime_error& e) {
    throw LoadError(path, e.what());
  }
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  checkJsonDepth(path, text);  // before the recursive parser
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw LoadError(path, std::string("invalid JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("model") || !doc["model"].is_string())
    throw LoadError(path, "a scene wrapper needs \"model\": the path of an .obj, .gltf or .glb");
  std::filesystem::path model = doc["model"].get<std::string>();
  if (model.is_relative()) model = path.parent_path() / model;
  if (model.extension() == ".json") throw LoadError(path, "a wrapper cannot wrap a wrapper");
  const float scale = numberOf(path, doc, "scale", 1.0f);
  if (!(scale > 0.0f)) throw LoadError(path, "'scale' must be positive");

  Scene scene = loadSceneAsWritten(model);  // its own errors name the model file
  // Uniform scale of every instance (lengths only: radiance and intensity do not change).
  const glm::mat4 toMetres = glm::scale(glm::mat4(1.0f), glm::vec3(scale));
  for (Instance& instance : scene.instances) instance.transform = toMetres * instance.transform;
  for (Light& light : scene.lights) light.position *= scale;
  for (Camera& camera : scene.cameras) {
    camera.cameraToWorld[3] = glm::vec4(glm::vec3(camera.cameraToWorld[3]) * scale, 1.0f);
    camera.znear *= scale;
    camera.zfar *= scale;
  }

  if (doc.contains("lights")) {
    if (!doc["lights"].is_array()) throw LoadError(path, "'lights' must be an array");
    for (const json& entry : doc["lights"]) scene.lights.push_back(lightOf(path, entry));
  }
  if (doc.contains("emitters")) {
    if (!doc["emitters"].is_array()) throw LoadError(path, "'emitters' must be an array");
    for (const json& entry : doc["emitters"]) addEmitter(path, entry, scene);
  }
  if (doc.contains("camera")) {
    const json& c = doc["camera"];
    if (!c.is_object()) throw LoadError(path, "'camera' must be an object");
    Camera camera;
    camera.name = c.value("name", std::string("wrapper"));
    const glm::vec3 eye = vec3Of(path, c.value("position", json()), "camera position");
    const glm::vec3 target = vec3Of(path, c.value("target", json()), "camera target");
    const glm::vec3 forward = target - eye;
    if (!(glm::length(forward) > 0.0f) ||
        glm::length(glm::cross(glm::normalize(forward), glm::vec3(0, 1, 0))) < 1e-4f)
      throw LoadError(path,
                      "camera target must differ from its position and not be straight up "
                      "or down");
    camera.cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
    camera.yfov = numberOf(path, c, "yfov", camera.yfov);
    camera.znear = numberOf(path, c, "znear", camera.znear);
    camera.zfar = numberOf(path, c, "zfar", camera.zfar);
    if (!(camera.yfov > 0.0f && camera.yfov < 3.1f) || !(camera.znear > 0.0f) ||
        !(camera.zfar > camera.znear))
      throw LoadError(path, "camera needs 0 < yfov < π and 0 < znear < zfar");
    scene.cameras.insert(scene.cameras.begin(), camera);
  }
  checkLimits(path, scene);
  return scene;
}

}  // namespace bounce
