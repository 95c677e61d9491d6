#include "render/forward_renderer.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "gl/draw_state.h"
#include "gl/mesh_buffer.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "render/view.h"
#include "scene/world_geometry.h"

namespace bounce {
namespace {

// Must match MAX_PUNCTUAL_LIGHTS and the LIGHT_* constants in shaders/lights.glsl.
constexpr std::size_t kMaxPunctualLights = 32;
int shaderLightType(LightType type) {
  switch (type) {
    case LightType::Point:
      return 0;
    case LightType::Spot:
      return 1;
    case LightType::Directional:
      return 2;
  }
  return 0;
}

// Texture units, as the fragment shader's samplers are told.
constexpr int kAlbedoUnit = 0;
constexpr int kEmitterUnit = 1;

// A run of triangles sharing a material: one draw call.
struct DrawRange {
  uint32_t material = 0;
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
};

}  // namespace

struct ForwardRenderer::Gpu {
  std::optional<gl::MeshBuffer> mesh;
  std::vector<DrawRange> ranges;
  std::vector<Material> materials;
  std::vector<gl::Texture2D> textures;
  std::optional<gl::Texture2D> emitters;  // 4 texels per emissive triangle, see area_light.glsl
  int emitterCount = 0;
  std::optional<gl::Program> forward;
  // Punctual lights as the uniform arrays of lights.glsl.
  std::vector<int> lightType;
  std::vector<glm::vec3> lightPosition, lightDirection, lightPower;
  std::vector<glm::vec2> lightCosCone;
};

ForwardRenderer::ForwardRenderer(const Scene& scene, const std::filesystem::path& shaderDir)
    : gpu_(std::make_unique<Gpu>()) {
  Gpu& gpu = *gpu_;
  gpu.forward.emplace(shaderDir / "forward.vert", shaderDir / "forward.frag");
  gpu.materials = scene.materials;
  if (gpu.materials.empty()) gpu.materials.emplace_back();

  // Geometry: world-space triangles sorted by material so each material is one draw.
  const WorldGeometry world = flatten(scene);
  std::vector<gl::Vertex> vertices(world.positions.size());
  for (std::size_t v = 0; v < vertices.size(); ++v)
    vertices[v] = {world.positions[v], world.normals[v], world.uv0[v]};
  std::vector<uint32_t> order(world.triangleCount());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return world.triangleMaterial[a] < world.triangleMaterial[b];
  });
  std::vector<uint32_t> indices;
  indices.reserve(order.size() * 3);
  std::vector<glm::vec4> emitterTable;
  for (uint32_t t : order) {
    uint32_t material = world.triangleMaterial[t];
    if (material >= gpu.materials.size()) material = 0;
    if (gpu.ranges.empty() || gpu.ranges.back().material != material)
      gpu.ranges.push_back({material, static_cast<uint32_t>(indices.size()), 0});
    const glm::uvec3 tri = world.triangles[t];
    indices.insert(indices.end(), {tri.x, tri.y, tri.z});
    gpu.ranges.back().indexCount += 3;
    const Material& m = gpu.materials[material];
    // A zero-area emitter gives no light (and its plane, hence the shader's facing test, is
    // undefined).
    if (m.isEmissive() && glm::length(world.triangleCross(t)) > 0.0f) {
      emitterTable.emplace_back(world.positions[tri.x], 0.0f);
      emitterTable.emplace_back(world.positions[tri.y], 0.0f);
      emitterTable.emplace_back(world.positions[tri.z], 0.0f);
      emitterTable.emplace_back(m.emission, m.doubleSided ? 1.0f : 0.0f);
    }
  }
  // Shading normals must be unit: a vertex without one (zero after flatten) takes the
  // area-weighted mean of its triangles' geometric normals.
  std::vector<glm::vec3> fallbackNormals(vertices.size(), glm::vec3(0.0f));
  bool missingNormals = false;
  for (std::size_t t = 0; t < world.triangleCount(); ++t) {
    const glm::vec3 cross = world.triangleCross(t);
    for (const uint32_t v : {world.triangles[t].x, world.triangles[t].y, world.triangles[t].z}) {
      if (glm::length(vertices[v].normal) > 0.0f) continue;
      fallbackNormals[v] += cross;
      missingNormals = true;
    }
  }
  if (missingNormals) {
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      const float length = glm::length(fallbackNormals[v]);
      if (length > 0.0f) vertices[v].normal = fallbackNormals[v] / length;
    }
  }
  gpu.mesh.emplace(vertices, indices);
  gl::checkErrors("scene upload");

  gpu.emitterCount = static_cast<int>(emitterTable.size() / 4);
  if (gpu.emitterCount > gl::Texture2D::maxSize()) {
    warnings_.push_back(std::to_string(gpu.emitterCount) + " emissive triangles; only the first " +
                        std::to_string(gl::Texture2D::maxSize()) + " light the scene");
    gpu.emitterCount = gl::Texture2D::maxSize();
    emitterTable.resize(static_cast<std::size_t>(gpu.emitterCount) * 4);
  }
  if (emitterTable.empty()) emitterTable.assign(4, glm::vec4(0.0f));  // samplers need a texture
  gpu.emitters.emplace(4, std::max(gpu.emitterCount, 1), emitterTable);
  if (gpu.emitterCount > 256)
    warnings_.push_back(std::to_string(gpu.emitterCount) +
                        " emissive triangles: each fragment loops over all of them (slow)");

  gpu.textures.reserve(scene.textures.size());
  for (const Texture& texture : scene.textures) {
    if (texture.width > 0 && texture.height > 0 &&
        texture.texels.size() ==
            static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height)) {
      gpu.textures.emplace_back(texture.width, texture.height, texture.texels, gl::Filter::Linear);
    } else {
      warnings_.push_back("texture '" + texture.name + "' has no texels; it is drawn white");
      const glm::vec3 white(1.0f);
      gpu.textures.emplace_back(1, 1, std::span(&white, 1), gl::Filter::Nearest);
    }
  }

  for (const Light& light : scene.lights) {
    if (gpu.lightType.size() == kMaxPunctualLights) {
      warnings_.push_back(std::to_string(scene.lights.size()) +
                          " punctual lights; only the first " + std::to_string(kMaxPunctualLights) +
                          " are drawn");
      break;
    }
    gpu.lightType.push_back(shaderLightType(light.type));
    gpu.lightPosition.push_back(light.position);
    gpu.lightDirection.push_back(glm::normalize(light.direction));
    gpu.lightPower.push_back(light.type == LightType::Directional ? light.irradiance
                                                                  : light.intensity);
    // The same cosines bounce::spotFalloff computes, so the shader's falloff matches it.
    gpu.lightCosCone.emplace_back(std::cos(light.innerConeAngle), std::cos(light.outerConeAngle));
  }
  if (gpu.lightType.empty() && gpu.emitterCount == 0)
    warnings_.push_back("the scene has no lights and no emissive surfaces: the image is black");
}

ForwardRenderer::~ForwardRenderer() = default;

std::size_t ForwardRenderer::emitterTriangleCount() const {
  return static_cast<std::size_t>(gpu_->emitterCount);
}

void ForwardRenderer::render(const Camera& camera, gl::RenderTarget& target) {
  Gpu& gpu = *gpu_;
  target.bind();
  gl::clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  gl::setDepthTest(true);

  gl::Program& program = *gpu.forward;
  const float aspect = static_cast<float>(target.width()) / static_cast<float>(target.height());
  program.set("uViewProjection", viewProjection(camera, aspect));
  program.set("uLightCount", static_cast<int>(gpu.lightType.size()));
  program.set("uLightType", std::span<const int>(gpu.lightType));
  program.set("uLightPosition", std::span<const glm::vec3>(gpu.lightPosition));
  program.set("uLightDirection", std::span<const glm::vec3>(gpu.lightDirection));
  program.set("uLightPower", std::span<const glm::vec3>(gpu.lightPower));
  program.set("uLightCosCone", std::span<const glm::vec2>(gpu.lightCosCone));
  program.set("uEmitterCount", gpu.emitterCount);
  program.set("uEmitters", kEmitterUnit);
  program.set("uAlbedoTexture", kAlbedoUnit);
  gpu.emitters->bind(kEmitterUnit);

  for (const DrawRange& range : gpu.ranges) {
    const Material& m = gpu.materials[range.material];
    // glTF: a single-sided surface is invisible from behind (and emits only forwards).
    gl::setBackFaceCulling(!m.doubleSided);
    program.set("uAlbedo", m.albedo);
    program.set("uEmission", m.emission);
    const bool textured = m.albedoTexture && *m.albedoTexture < gpu.textures.size();
    program.set("uHasAlbedoTexture", textured ? 1 : 0);
    if (textured) gpu.textures[*m.albedoTexture].bind(kAlbedoUnit);
    gpu.mesh->draw(range.firstIndex, range.indexCount);
  }
  gl::setBackFaceCulling(false);
  gl::checkErrors("forward pass");
}

Image ForwardRenderer::renderImage(const Camera& camera, int width, int height) {
  gl::RenderTarget target(width, height);
  render(camera, target);
  return target.read();
}

}  // namespace bounce
