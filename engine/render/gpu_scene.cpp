#include "render/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/area_light_outline.h"
#include "scene/surface_rules.h"

namespace bounce {
namespace {

// A mesh's corners in `indices` order; each corner's normal is the mesh's, or the triangle's
// geometric normal where that one is unusable (surface_rules.h: shadingNormalOr, the rule the
// path tracer applies per corner too).
std::vector<gl::Vertex> meshCorners(const Mesh& mesh) {
  std::vector<gl::Vertex> corners;
  corners.reserve(mesh.indices.size() / 3 * 3);
  const auto position = [&](uint32_t v) {
    return v < mesh.positions.size() ? mesh.positions[v] : glm::vec3(0.0f);
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 cross = glm::cross(position(mesh.indices[t + 1]) - position(mesh.indices[t]),
                                       position(mesh.indices[t + 2]) - position(mesh.indices[t]));
    const float length = glm::length(cross);
    const glm::vec3 flat = length > 0.0f ? cross / length : glm::vec3(0.0f);
    for (std::size_t c = 0; c < 3; ++c) {
      const uint32_t v = mesh.indices[t + c];
      const glm::vec3 n = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0.0f);
      const glm::vec2 uv = v < mesh.uv0.size() ? mesh.uv0[v] : glm::vec2(0.0f);
      corners.push_back({position(v), shadingNormalOr(n, flat), uv});
    }
  }
  return corners;
}

Box meshBox(const Mesh& mesh) {
  Box box;
  for (const glm::vec3& p : mesh.positions) box.grow(p);
  return box;
}

// The material index a draw uses: the scene's, or the absorber appended after them.
uint32_t drawnMaterial(const Scene& scene, uint32_t index) {
  return index < scene.materials.size() ? index : static_cast<uint32_t>(scene.materials.size());
}

GpuMaterial gpuMaterial(const Material& m, std::size_t textureCount) {
  GpuMaterial g;
  g.reflectance = reflectance(m);
  g.emission = emittedRadiance(m);
  g.doubleSided = m.doubleSided;
  if (m.albedoTexture && *m.albedoTexture < textureCount)
    g.texture = static_cast<int>(*m.albedoTexture);
  return g;
}

// The largest distance (m) of a vertex from the mesh box's centre.
float meshRadius(const Mesh& mesh, const Box& box) {
  const glm::vec3 centre = 0.5f * (box.lower + box.upper);
  float r2 = 0.0f;
  for (const glm::vec3& p : mesh.positions) r2 = std::max(r2, glm::dot(p - centre, p - centre));
  return std::sqrt(r2);
}

void placeInstance(GpuInstance& instance, const glm::mat4& transform, const Box& meshBox,
                   float meshRadius) {
  instance.model = transform;
  const glm::mat3 linear(transform);
  instance.normalMatrix = glm::transpose(glm::inverse(linear));
  instance.mirrored = glm::determinant(linear) < 0.0f;
  instance.worldBox = transformBox(meshBox, transform);
  if (meshBox.empty()) return;
  const float scale =
      std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  const glm::vec3 centre(transform * glm::vec4(0.5f * (meshBox.lower + meshBox.upper), 1.0f));
  instance.worldSphere = glm::vec4(centre, meshRadius * scale);
}

}  // namespace

GpuScene::GpuScene(const Scene& scene, std::vector<std::string>& warnings)
    : scene_(scene), warnings_(&warnings) {
  for (const Mesh& mesh : scene.meshes) {
    meshes_.push_back(std::make_unique<gl::MeshBuffer>(meshCorners(mesh)));
    meshBoxes_.push_back(meshBox(mesh));
    meshRadii_.push_back(meshRadius(mesh, meshBoxes_.back()));
  }
  for (const Material& m : scene.materials)
    materials_.push_back(gpuMaterial(m, scene.textures.size()));
  materials_.push_back(gpuMaterial(materialOf(scene, ~0u), 0));  // the absorber

  instances_.reserve(scene.instances.size());
  lightmapUv_.resize(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes.at(instance.mesh);
    GpuInstance gpu{instance.mesh,
                    drawnMaterial(scene, mesh.material),
                    instance.mobility,
                    {},
                    {},
                    false,
                    {},
                    gl::VertexArray(*meshes_[instance.mesh])};
    placeInstance(gpu, instance.transform, meshBoxes_[instance.mesh], meshRadii_[instance.mesh]);
    instances_.push_back(std::move(gpu));
  }

  textures_.reserve(scene.textures.size());
  for (const Texture& texture : scene.textures) {
    if (texture.width > 0 && texture.height > 0 &&
        texture.texels.size() ==
            static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height)) {
      textures_.emplace_back(texture.width, texture.height, texture.texels, gl::Filter::Linear);
    } else {
      warnings.push_back("texture '" + texture.name + "' has no texels; it is drawn white");
      const glm::vec3 white(1.0f);
      textures_.emplace_back(1, 1, std::span(&white, 1), gl::Filter::Nearest);
    }
  }
  uploadEmitters();
  if (emitterCount_ > 256)
    warnings.push_back(
        std::to_string(emitterCount_) + " emissive triangles in " +
        std::to_string(areaLights_.lights.size()) +
        " area lights: each fragment loops over every triangle of the lights in its view cluster "
        "(all of them without light culling; slow)");
}

GpuScene::~GpuScene() = default;

SceneLimits GpuScene::sceneLimits() {
  const auto rows = static_cast<std::size_t>(gl::Texture2D::maxSize());
  SceneLimits limits;
  limits.maxEmissiveTriangles = rows - 1;
  limits.emissiveLimitReason =
      "the renderer's emitter table holds GL_MAX_TEXTURE_SIZE = " + std::to_string(rows) +
      " rows, one per emissive triangle and one per area light, and evaluates every triangle's "
      "exact irradiance per pixel: merge the emitter into fewer, larger triangles";
  return limits;
}

void GpuScene::uploadEmitters() {
  // The area lights cut by their shape (scene/area_lights.h) at the instances' current places,
  // their triangles 4 texels a row, then one row per light: see shaders/area_light.glsl.
  std::vector<glm::mat4> models;
  for (const GpuInstance& instance : instances_) models.push_back(instance.model);
  AreaLightSet lights = sceneAreaLights(scene_, models);
  const bool first = !emitters_.has_value();
  const std::size_t rowLimit = static_cast<std::size_t>(gl::Texture2D::maxSize());
  if (lights.triangles.size() + lights.lights.size() > rowLimit) {
    // Whole lights only, in order (the static ones first): the rest are dropped.
    std::size_t keep = 0;
    while (keep < lights.lights.size() &&
           lights.lights[keep].first + lights.lights[keep].count + keep + 1 <= rowLimit)
      ++keep;
    if (first)
      warnings_->push_back(std::to_string(lights.lights.size()) + " area lights (" +
                           std::to_string(lights.triangles.size()) +
                           " emissive triangles); only the first " + std::to_string(keep) +
                           " light the scene");
    const std::size_t triangles =
        keep == 0 ? 0 : lights.lights[keep - 1].first + lights.lights[keep - 1].count;
    lights.lights.resize(keep);
    lights.triangles.resize(triangles);
    lights.cumulativeArea.resize(triangles);
  }
  std::vector<glm::vec4> table;
  for (const EmitterTriangle& e : lights.triangles) {
    for (const glm::vec3& corner : {e.v0, e.v1, e.v2}) table.emplace_back(corner, 0.0f);
    table.emplace_back(e.radiance, e.doubleSided ? 1.0f : 0.0f);
  }
  // Each light's outline where it has one (scene/area_light_outline.h), after the light rows,
  // 4 corners a row; the light's row names its first corner and their count (0: its triangles).
  std::vector<glm::vec4> corners;
  for (const AreaLight& light : lights.lights) {
    const auto outline = areaLightOutline(lights, light);
    const std::size_t outlineRows = (corners.size() + (outline ? outline->size() : 0) + 3) / 4;
    const bool fits =
        outline && lights.triangles.size() + lights.lights.size() + outlineRows <= rowLimit;
    const EmitterTriangle& triangle = lights.triangles[light.first];
    table.emplace_back(
        static_cast<float>(light.first), static_cast<float>(light.first + light.count),
        light.bakeDirect ? 1.0f : 0.0f, fits ? static_cast<float>(outline->size()) : 0.0f);
    table.emplace_back(light.normal, static_cast<float>(corners.size()));
    table.emplace_back(triangle.radiance, triangle.doubleSided ? 1.0f : 0.0f);
    table.emplace_back(0.0f);
    if (fits)
      for (const glm::vec3& corner : *outline) corners.emplace_back(corner, 0.0f);
  }
  corners.resize((corners.size() + 3) / 4 * 4, glm::vec4(0.0f));
  table.insert(table.end(), corners.begin(), corners.end());
  emitterCount_ = static_cast<int>(lights.triangles.size());
  areaLights_ = std::move(lights);
  ++emitterVersion_;
  if (table.empty()) table.assign(4, glm::vec4(0.0f));  // samplers need a texture
  emitters_.reset();
  emitters_.emplace(4, static_cast<int>(table.size() / 4), table);
}

void GpuScene::setInstanceTransform(std::size_t index, const glm::mat4& transform) {
  GpuInstance& instance = instances_.at(index);
  placeInstance(instance, transform, meshBoxes_[instance.mesh], meshRadii_[instance.mesh]);
  if (materials_[instance.material].emission != glm::vec3(0.0f)) uploadEmitters();
}

void GpuScene::setLightmapUv(std::size_t index, std::span<const glm::vec2> cornerUv) {
  GpuInstance& instance = instances_.at(index);
  if (cornerUv.empty()) {
    instance.vertexArray.setLightmapUv(nullptr);
    lightmapUv_[index].reset();
    return;
  }
  auto attribute = std::make_unique<gl::CornerAttribute>(cornerUv);
  instance.vertexArray.setLightmapUv(attribute.get());
  lightmapUv_[index] = std::move(attribute);
}

Box GpuScene::bounds() const {
  Box box;
  for (const GpuInstance& instance : instances_) {
    if (instance.worldBox.empty()) continue;
    box.grow(instance.worldBox.lower);
    box.grow(instance.worldBox.upper);
  }
  return box;
}

void GpuScene::draw(const GpuInstance& instance, gl::Program& program) const {
  program.set("uModel", instance.model);
  program.set("uNormalMatrix", instance.normalMatrix);
  instance.vertexArray.draw();
}

const GpuMaterial& GpuScene::bindMaterial(const GpuInstance& instance, gl::Program& program,
                                          int albedoUnit) const {
  const GpuMaterial& m = materials_[instance.material];
  program.set("uAlbedo", m.reflectance);
  program.set("uEmission", m.emission);
  program.set("uHasAlbedoTexture", m.texture >= 0 ? 1 : 0);
  if (m.texture >= 0) textures_[static_cast<std::size_t>(m.texture)].bind(albedoUnit);
  return m;
}

}  // namespace bounce
