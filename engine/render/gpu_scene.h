// The scene as the passes draw it: one MeshBuffer per mesh (uploaded once, de-indexed, see
// gl/vertex_attributes.h), one GpuInstance per instance with its own model matrix (moving an
// instance re-uploads nothing but its matrices, and the emitter table when it emits), the
// materials as the shader reads them (scene/surface_rules.h), the textures and the area-light
// table of shaders/area_light.glsl. Needs a current GL context for its whole life.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/mesh_buffer.h"
#include "gl/shader.h"
#include "gl/texture.h"
#include "render/frustum.h"
#include "render/gpu_instance.h"
#include "scene/area_lights.h"
#include "scene/load.h"
#include "scene/scene.h"

namespace bounce {

struct GpuMaterial {
  glm::vec3 reflectance{0.0f};  // ρ in [0,1] (surface_rules.h: reflectance)
  glm::vec3 emission{0.0f};     // Le, W/(sr·m²) (surface_rules.h: emittedRadiance)
  bool doubleSided = false;
  int texture = -1;  // index into the scene's textures, -1 for none
};

class GpuScene {
 public:
  // Appends what the GPU cannot represent (too many emitters, empty textures) to `warnings`.
  GpuScene(const Scene& scene, std::vector<std::string>& warnings);
  // What loadScene may hand this context's GpuScene: at most GL_MAX_TEXTURE_SIZE − 1 emissive
  // triangles (the emitter table's rows, one per triangle and one per area light; beyond, lights
  // are dropped from the frame). Needs a current context.
  static SceneLimits sceneLimits();
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  // Moves instance `index` (object → world); throws std::out_of_range for a bad index.
  void setInstanceTransform(std::size_t index, const glm::mat4& transform);
  // Gives instance `index` per-corner lightmap UVs (3 per triangle in its mesh's `indices`
  // order, vertex attribute 3); an empty span removes them. Throws std::invalid_argument when
  // the count does not match the mesh.
  void setLightmapUv(std::size_t index, std::span<const glm::vec2> cornerUv);

  std::span<const GpuInstance> instances() const { return instances_; }
  // The scene it was made from (static instances stand at its transforms).
  const Scene& source() const { return scene_; }
  const std::vector<GpuMaterial>& materials() const { return materials_; }
  // World bounds of every instance (metres); empty for an empty scene.
  Box bounds() const;
  // Emissive triangles uploaded (the area lights' rows of the emitter table).
  int emitterCount() const { return emitterCount_; }
  // The area lights as uploaded (scene/area_lights.h; their triangles are the emitter table's
  // rows in order, shaders/area_light.glsl), and a count that changes whenever they are cut
  // again (an emitting instance moved). For area-light shadows and baked visibility.
  const AreaLightSet& areaLights() const { return areaLights_; }
  int areaLightCount() const { return static_cast<int>(areaLights_.lights.size()); }
  int emitterVersion() const { return emitterVersion_; }

  // Sets uModel and uNormalMatrix for `instance`, then draws it.
  void draw(const GpuInstance& instance, gl::Program& program) const;
  // Binds material textures (albedo at `albedoUnit`) and sets uAlbedo, uEmission,
  // uHasAlbedoTexture of the forward shader; returns the material.
  const GpuMaterial& bindMaterial(const GpuInstance& instance, gl::Program& program,
                                  int albedoUnit) const;
  void bindEmitters(int unit) const { emitters_->bind(unit); }

 private:
  void uploadEmitters();

  const Scene& scene_;
  std::vector<std::unique_ptr<gl::MeshBuffer>> meshes_;
  std::vector<Box> meshBoxes_;  // object space
  std::vector<float>
      meshRadii_;  // m, object space: the vertices' largest distance from the box centre
  std::vector<std::unique_ptr<gl::CornerAttribute>> lightmapUv_;  // per instance, may be null
  std::vector<GpuInstance> instances_;
  std::vector<GpuMaterial> materials_;
  std::vector<gl::Texture2D> textures_;
  std::optional<gl::Texture2D> emitters_;
  int emitterCount_ = 0;
  AreaLightSet areaLights_;
  int emitterVersion_ = 0;
  std::vector<std::string>* warnings_ = nullptr;
};

}  // namespace bounce
