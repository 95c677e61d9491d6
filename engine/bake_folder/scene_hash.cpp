#include "bake_folder/scene_hash.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "scene/aggregate_fields.h"

namespace bounce {
namespace {

// Every field of every scene struct is hashed below or named there as not changing a bake.
// When one of these fails, a field was added to scene/scene.h: hash it in the function of its
// part (or write there why it cannot change a bake), add its case to
// tests/bake_io/scene_hash_test.cpp, and update the count here and there.
static_assert(aggregateFieldCount<Texture>() == 4, "Texture changed: extend the scene hash");
static_assert(aggregateFieldCount<Material>() == 6, "Material changed: extend the scene hash");
static_assert(aggregateFieldCount<Mesh>() == 8, "Mesh changed: extend the scene hash");
static_assert(aggregateFieldCount<Instance>() == 5, "Instance changed: extend the scene hash");
static_assert(aggregateFieldCount<Light>() == 10, "Light changed: extend the scene hash");
static_assert(aggregateFieldCount<Scene>() == 8, "Scene changed: extend the scene hash");

// FNV-1a (64 bit) over a little-endian serialisation, each array's length first so that moving
// a value from one array to the next changes the hash.
class ContentHash {
 public:
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      state_ ^= p[i];
      state_ *= 0x100000001b3ull;
    }
  }
  void u64(uint64_t v) {
    unsigned char b[8];
    for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(v >> (8 * i));
    bytes(b, 8);
  }
  // Bit pattern, with −0 as +0 and every NaN as one NaN: equal values hash equal.
  void f32(float v) {
    if (v == 0.0f) v = 0.0f;
    if (std::isnan(v)) v = std::numeric_limits<float>::quiet_NaN();
    u64(std::bit_cast<uint32_t>(v));
  }
  void vec(const glm::vec2& v) { f32(v.x), f32(v.y); }
  void vec(const glm::vec3& v) { f32(v.x), f32(v.y), f32(v.z); }
  void mat(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) f32(m[c][r]);
  }
  template <class T>
  void array(const std::vector<T>& values) {
    u64(values.size());
    for (const T& v : values) vec(v);
  }
  uint64_t state() const { return state_; }

 private:
  uint64_t state_ = 0xcbf29ce484222325ull;
};

std::string hex(uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 0; i < 16; ++i) s[15 - i] = digits[(v >> (4 * i)) & 0xf];
  return s;
}

uint64_t hashMeshes(const std::vector<Mesh>& meshes) {
  ContentHash h;
  h.u64(meshes.size());
  for (const Mesh& mesh : meshes) {  // not its name
    h.array(mesh.positions);
    h.array(mesh.normals);
    h.array(mesh.uv0);
    h.array(mesh.uv1);
    h.u64(mesh.indices.size());
    for (uint32_t i : mesh.indices) h.u64(i);
    h.u64(mesh.material);
    // The charts follow the cuts (scene/crossing_cuts.h); scenes without any hash as before.
    if (!mesh.cutEdges.empty()) {
      h.u64(mesh.cutEdges.size());
      for (const uint8_t c : mesh.cutEdges) h.u64(c);
    }
  }
  return h.state();
}

uint64_t hashMaterials(const std::vector<Material>& materials) {
  ContentHash h;
  h.u64(materials.size());
  for (const Material& m : materials) {  // not its name
    h.vec(m.albedo);
    h.u64(m.albedoTexture ? uint64_t{*m.albedoTexture} + 1 : 0);
    h.vec(m.emission);
    h.u64(m.doubleSided ? 1 : 0);
    h.u64(m.bakeDirect ? 1 : 0);  // whether its direct light is in the map
  }
  return h.state();
}

uint64_t hashTextures(const std::vector<Texture>& textures) {
  ContentHash h;
  h.u64(textures.size());
  for (const Texture& t : textures) {  // not its name
    h.u64(static_cast<uint32_t>(t.width));
    h.u64(static_cast<uint32_t>(t.height));
    h.array(t.texels);
  }
  return h.state();
}

uint64_t hashInstances(const std::vector<Instance>& instances) {
  ContentHash h;
  h.u64(instances.size());
  for (const Instance& instance : instances) {  // not its name
    // Mobility first: it decides whether a transform follows.
    h.u64(static_cast<uint64_t>(instance.mobility));
    h.u64(instance.mesh);
    // A dynamic instance is in neither the lightmap nor the VPLs (the bake runs without it):
    // the bake holds wherever it is placed, so its transform is left out.
    if (instance.mobility == Mobility::Static) {
      h.mat(instance.transform);
      h.f32(instance.lightmapScale);  // sets its texels (a dynamic instance has none)
    }
  }
  return h.state();
}

uint64_t hashLights(const std::vector<Light>& lights) {
  ContentHash h;
  h.u64(lights.size());
  for (const Light& light : lights) {  // not its name
    h.u64(static_cast<uint64_t>(light.type));
    h.vec(light.position);
    h.vec(light.direction);
    h.vec(light.intensity);
    h.vec(light.irradiance);
    h.f32(light.innerConeAngle);
    h.f32(light.outerConeAngle);
    h.u64(light.bakeDirect ? 1 : 0);               // whether its direct light is in the map
    h.u64(static_cast<uint64_t>(light.mobility));  // whether the bake holds its light
  }
  return h.state();
}

}  // namespace

SceneHash sceneHash(const Scene& scene) {
  // Scene::source, cameras and warnings do not change light.
  const std::array<uint64_t, kScenePartNames.size()> parts = {
      hashMeshes(scene.meshes), hashMaterials(scene.materials), hashTextures(scene.textures),
      hashInstances(scene.instances), hashLights(scene.lights)};
  ContentHash whole;
  SceneHash result;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    whole.u64(parts[i]);
    result.parts[i] = hex(parts[i]);
  }
  result.whole = hex(whole.state());
  return result;
}

std::string sceneContentHash(const Scene& scene) {
  return sceneHash(scene).whole;
}

}  // namespace bounce
