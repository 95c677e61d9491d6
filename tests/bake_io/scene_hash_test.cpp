// The scene hash (engine/bake_folder/scene_hash.h) against every field of the scene model: each
// field that changes a bake, edited alone by the smallest step there is (the next float, one
// index), changes the hash and only its part's hash; names, cameras, warnings, the source path and
// where a dynamic instance stands keep it. Each struct's field list is checked against the struct's
// field count, so a field added to scene/scene.h fails here until it has its case (and the
// static_asserts in scene_hash.cpp until the hash covers it).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "bake_folder/scene_hash.h"
#include "scene/aggregate_fields.h"

using namespace bounce;

namespace {

enum class Expect { Changes, Keeps, ChangesUnlessDynamic };

template <class T>
using Edit = std::function<void(T&)>;

template <class T>
struct Field {
  std::string name;
  Expect expect;
  std::vector<Edit<T>> edits;  // each applied alone to a fresh scene
};

void bump(float& v) {
  v = std::nextafter(v, std::numeric_limits<float>::infinity());
}

// One edit per component of a glm vector or matrix field.
template <class T, class V>
std::vector<Edit<T>> eachComponent(V T::*field) {
  std::vector<Edit<T>> edits;
  for (int c = 0; c < V::length(); ++c) {
    if constexpr (std::is_same_v<V, glm::mat4>) {
      for (int r = 0; r < 4; ++r) edits.push_back([=](T& t) { bump((t.*field)[c][r]); });
    } else {
      edits.push_back([=](T& t) { bump((t.*field)[c]); });
    }
  }
  return edits;
}

// One edit per component of each of the first `count` elements of an array field, plus one more
// element and one fewer. Every array in richScene() has at least 3 elements.
template <class T, class V>
std::vector<Edit<T>> eachElement(std::vector<V> T::*field, std::size_t count) {
  std::vector<Edit<T>> edits;
  for (std::size_t i = 0; i < count; ++i) {
    if constexpr (std::is_same_v<V, uint32_t>) {
      edits.push_back([=](T& t) { (t.*field).at(i) += 1; });
    } else {
      for (int c = 0; c < V::length(); ++c)
        edits.push_back([=](T& t) { bump((t.*field).at(i)[c]); });
    }
  }
  edits.push_back([=](T& t) { (t.*field).push_back((t.*field).back()); });
  edits.push_back([=](T& t) { (t.*field).pop_back(); });
  return edits;
}

template <class T>
Edit<T> flip(bool T::*field) {
  return [=](T& t) { t.*field = !(t.*field); };
}

template <class T>
Edit<T> plusOne(uint32_t T::*field) {
  return [=](T& t) { t.*field += 1; };
}

template <class T>
Edit<T> rename(std::string T::*field) {
  return [=](T& t) { t.*field += " renamed"; };
}

template <class T>
std::vector<Edit<T>> bumpFloat(float T::*field) {
  return {[=](T& t) { bump(t.*field); }};
}

// Two meshes, three materials (two textured, one emissive and double-sided), two textures,
// three instances (static, dynamic, static again scaled), one light of each type, a camera and a
// warning. Every array holds at least 3 elements (eachElement edits the first 3).
Scene richScene() {
  Scene s;
  s.source = "rich.gltf";
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  quad.normals.assign(4, {0, 1, 0});
  quad.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.uv1 = {{0.1f, 0.1f}, {0.4f, 0.1f}, {0.4f, 0.4f}, {0.1f, 0.4f}};
  quad.indices = {0, 2, 1, 0, 3, 2};
  quad.cutEdges = {0x12, 0};  // edge 1 of triangle 0 cut and crossed (scene/crossing_cuts.h)
  Mesh tri;
  tri.name = "tri";
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.normals.assign(3, {0, 0, 1});
  tri.uv0 = {{0, 0}, {1, 0}, {0, 1}};
  tri.uv1 = {{0.5f, 0.5f}, {0.9f, 0.5f}, {0.5f, 0.9f}};
  tri.indices = {0, 1, 2};
  tri.cutEdges = {0x01};
  tri.material = 1;
  s.meshes = {quad, tri};
  Material white{"white", glm::vec3(0.8f), std::nullopt, glm::vec3(0.0f), false, false};
  Material red{"red", {0.7f, 0.1f, 0.1f}, 0u, glm::vec3(0.0f), false, false};
  Material lamp{"lamp", glm::vec3(0.5f), 1u, {4.0f, 3.0f, 2.0f}, true, false};
  s.materials = {white, red, lamp};
  s.textures = {{"checker", 3, 1, {{1, 1, 1}, {0.5f, 0.5f, 0.5f}, {0.2f, 0.3f, 0.4f}}},
                {"column", 1, 3, {{0.9f, 0.8f, 0.7f}, {0.1f, 0.2f, 0.3f}, {0.6f, 0.6f, 0.6f}}}};
  s.instances = {{"floor", 0, glm::mat4(1.0f), Mobility::Static},
                 {"mover", 1, glm::mat4(1.0f), Mobility::Dynamic},
                 {"big", 1, glm::mat4(2.0f), Mobility::Static}};
  s.instances[2].transform[3] = {0.5f, 0.25f, -1.0f, 1.0f};
  Light point{"bulb", LightType::Point, {0, 2, 0}, {0, -1, 0}, {10, 9, 8}, glm::vec3(0.0f)};
  Light spot{"spot",       LightType::Spot, {1, 2, 1}, {0, -0.6f, -0.8f},
             {20, 20, 20}, glm::vec3(0.0f), 0.3f,      0.6f};
  Light sun{"sun",           LightType::Directional, glm::vec3(0.0f), {0.6f, -0.8f, 0.0f},
            glm::vec3(0.0f), {3.0f, 2.5f, 2.0f}};
  sun.bakeDirect = true;
  s.lights = {point, spot, sun};
  Camera camera;
  camera.name = "front";
  camera.cameraToWorld[3] = {0, 1, 3, 1};
  s.cameras = {camera};
  s.warnings = {"ignored emissiveTexture"};
  return s;
}

std::set<std::string> changedParts(const SceneHash& a, const SceneHash& b) {
  std::set<std::string> changed;
  for (std::size_t i = 0; i < kScenePartNames.size(); ++i)
    if (a.parts[i] != b.parts[i]) changed.insert(kScenePartNames[i]);
  return changed;
}

// Applies every edit of every field to every element of scene.*items, one at a time, and checks
// the hash against the field's expectation; a change must show in `part` only.
template <class T>
void checkEveryField(const char* type, std::vector<T> Scene::*items,
                     const std::vector<Field<T>>& fields, const std::string& part) {
  std::set<std::string> names;
  for (const Field<T>& field : fields) names.insert(field.name);
  // A field added to T: give it its case here (and hash it in scene_hash.cpp if it changes a
  // bake), then the counts agree again.
  ASSERT_EQ(names.size(), fields.size()) << type << ": a field listed twice";
  ASSERT_EQ(fields.size(), aggregateFieldCount<T>())
      << type << " has " << aggregateFieldCount<T>() << " fields, this test lists " << fields.size()
      << ": add the new field's case (and hash it in scene_hash.cpp)";
  const Scene base = richScene();
  const SceneHash before = sceneHash(base);
  for (std::size_t i = 0; i < (base.*items).size(); ++i) {
    for (const Field<T>& field : fields) {
      bool changes = field.expect == Expect::Changes;
      if constexpr (std::is_same_v<T, Instance>)
        if (field.expect == Expect::ChangesUnlessDynamic)
          changes = (base.*items)[i].mobility != Mobility::Dynamic;
      ASSERT_FALSE(field.edits.empty()) << type << "::" << field.name;
      for (std::size_t e = 0; e < field.edits.size(); ++e) {
        Scene s = base;
        field.edits[e]((s.*items)[i]);
        const SceneHash after = sceneHash(s);
        const std::string what = std::string(type) + " " + std::to_string(i) + "::" + field.name +
                                 ", edit " + std::to_string(e);
        if (changes) {
          EXPECT_NE(before.whole, after.whole) << what;
          EXPECT_EQ(changedParts(before, after), std::set<std::string>{part}) << what;
        } else {
          EXPECT_EQ(before.whole, after.whole) << what;
          EXPECT_EQ(changedParts(before, after), std::set<std::string>{}) << what;
        }
      }
    }
  }
}

TEST(SceneHash, EveryLightFieldOfEveryLightType) {
  checkEveryField<Light>("Light", &Scene::lights,
                         {{"name", Expect::Keeps, {rename(&Light::name)}},
                          {"type",
                           Expect::Changes,
                           {[](Light& l) { l.type = LightType((int(l.type) + 1) % 3); },
                            [](Light& l) { l.type = LightType((int(l.type) + 2) % 3); }}},
                          {"position", Expect::Changes, eachComponent(&Light::position)},
                          {"direction", Expect::Changes, eachComponent(&Light::direction)},
                          {"intensity", Expect::Changes, eachComponent(&Light::intensity)},
                          {"irradiance", Expect::Changes, eachComponent(&Light::irradiance)},
                          {"innerConeAngle", Expect::Changes, bumpFloat(&Light::innerConeAngle)},
                          {"outerConeAngle", Expect::Changes, bumpFloat(&Light::outerConeAngle)},
                          {"bakeDirect", Expect::Changes, {flip(&Light::bakeDirect)}},
                          {"mobility", Expect::Changes, {[](Light& l) {
                             l.mobility = l.mobility == Mobility::Static ? Mobility::Dynamic
                                                                         : Mobility::Static;
                           }}}},
                         "lights");
}

TEST(SceneHash, EveryMaterialField) {
  checkEveryField<Material>(
      "Material", &Scene::materials,
      {{"name", Expect::Keeps, {rename(&Material::name)}},
       {"albedo", Expect::Changes, eachComponent(&Material::albedo)},
       {"albedoTexture",
        Expect::Changes,
        {[](Material& m) { m.albedoTexture = m.albedoTexture ? std::nullopt : std::optional(0u); },
         [](Material& m) { m.albedoTexture = m.albedoTexture.value_or(0u) + 1; }}},
       {"emission", Expect::Changes, eachComponent(&Material::emission)},
       {"doubleSided", Expect::Changes, {flip(&Material::doubleSided)}},
       {"bakeDirect", Expect::Changes, {flip(&Material::bakeDirect)}}},
      "materials");
}

TEST(SceneHash, EveryTextureFieldAndTexel) {
  checkEveryField<Texture>("Texture", &Scene::textures,
                           {{"name", Expect::Keeps, {rename(&Texture::name)}},
                            {"width", Expect::Changes, {[](Texture& t) { t.width += 1; }}},
                            {"height", Expect::Changes, {[](Texture& t) { t.height += 1; }}},
                            // Every texel's every channel, and a texel more or fewer.
                            {"texels", Expect::Changes, eachElement(&Texture::texels, 3)}},
                           "textures");
  // The same texels as 3×1 or 1×3 are another texture.
  Scene transposed = richScene();
  std::swap(transposed.textures[0].width, transposed.textures[0].height);
  EXPECT_NE(sceneContentHash(richScene()), sceneContentHash(transposed));
}

TEST(SceneHash, EveryMeshFieldAndElement) {
  checkEveryField<Mesh>(
      "Mesh", &Scene::meshes,
      {{"name", Expect::Keeps, {rename(&Mesh::name)}},
       {"positions", Expect::Changes, eachElement(&Mesh::positions, 3)},
       {"normals", Expect::Changes, eachElement(&Mesh::normals, 3)},
       {"uv0", Expect::Changes, eachElement(&Mesh::uv0, 3)},
       {"uv1", Expect::Changes, eachElement(&Mesh::uv1, 3)},
       {"indices", Expect::Changes, eachElement(&Mesh::indices, 3)},
       {"material", Expect::Changes, {plusOne(&Mesh::material)}},
       // The charts follow the cuts: every bit, and their presence, counts.
       {"cutEdges",
        Expect::Changes,
        {[](Mesh& m) { m.cutEdges.at(0) ^= 0x01; }, [](Mesh& m) { m.cutEdges.at(0) ^= 0x08; },
         [](Mesh& m) { m.cutEdges.push_back(0); }, [](Mesh& m) { m.cutEdges.clear(); }}}},
      "meshes");
}

// Where a dynamic instance stands is no part of the bake (bounce-bake bakes without it): moving
// it (--move, the viewer) keeps the bake current. Its mesh and its mobility do count; a static
// instance's lightmapScale sets its texels.
TEST(SceneHash, EveryInstanceFieldButADynamicInstancesTransform) {
  ASSERT_EQ(richScene().instances[1].mobility, Mobility::Dynamic);
  checkEveryField<Instance>(
      "Instance", &Scene::instances,
      {{"name", Expect::Keeps, {rename(&Instance::name)}},
       {"mesh", Expect::Changes, {plusOne(&Instance::mesh)}},
       {"transform", Expect::ChangesUnlessDynamic, eachComponent(&Instance::transform)},
       {"mobility", Expect::Changes, {[](Instance& i) {
          i.mobility = i.mobility == Mobility::Static ? Mobility::Dynamic : Mobility::Static;
        }}},
       // A dynamic instance has no lightmap, so its scale is no part of the bake either.
       {"lightmapScale", Expect::ChangesUnlessDynamic, {[](Instance& i) {
          i.lightmapScale *= 2.0f;
        }}}},
      "instances");
}

TEST(SceneHash, CamerasDoNotCount) {
  checkEveryField<Camera>("Camera", &Scene::cameras,
                          {{"name", Expect::Keeps, {rename(&Camera::name)}},
                           {"cameraToWorld", Expect::Keeps, eachComponent(&Camera::cameraToWorld)},
                           {"yfov", Expect::Keeps, bumpFloat(&Camera::yfov)},
                           {"aspect", Expect::Keeps, bumpFloat(&Camera::aspect)},
                           {"znear", Expect::Keeps, bumpFloat(&Camera::znear)},
                           {"zfar", Expect::Keeps, bumpFloat(&Camera::zfar)}},
                          "");
}

// The scene's own fields: one element more or fewer in each array.
TEST(SceneHash, EverySceneArrayButCamerasAndWarnings) {
  struct SceneField {
    const char* name;
    const char* part;  // nullptr: keeps the hash
    std::vector<Edit<Scene>> edits;
  };
  const std::vector<SceneField> fields = {
      {"source", nullptr, {[](Scene& s) { s.source = "elsewhere/other.gltf"; }}},
      {"meshes",
       "meshes",
       {[](Scene& s) { s.meshes.push_back(s.meshes[0]); }, [](Scene& s) { s.meshes.pop_back(); }}},
      {"materials",
       "materials",
       {[](Scene& s) { s.materials.push_back(s.materials[0]); },
        [](Scene& s) { s.materials.pop_back(); }}},
      {"textures",
       "textures",
       {[](Scene& s) { s.textures.push_back(s.textures[0]); },
        [](Scene& s) { s.textures.pop_back(); }}},
      {"instances",
       "instances",
       {[](Scene& s) { s.instances.push_back(s.instances[0]); },
        [](Scene& s) { s.instances.pop_back(); },
        // A dynamic instance added or removed counts too: it is an instance the bake left out.
        [](Scene& s) { s.instances.push_back(s.instances[1]); },
        [](Scene& s) { s.instances.erase(s.instances.begin() + 1); }}},
      {"lights",
       "lights",
       {[](Scene& s) { s.lights.push_back(s.lights[0]); }, [](Scene& s) { s.lights.clear(); }}},
      {"cameras",
       nullptr,
       {[](Scene& s) { s.cameras.push_back(Camera{}); }, [](Scene& s) { s.cameras.clear(); }}},
      {"warnings", nullptr, {[](Scene& s) { s.warnings.push_back("another"); }}},
  };
  ASSERT_EQ(fields.size(), aggregateFieldCount<Scene>())
      << "Scene gained a field: add its case here (and hash it in scene_hash.cpp)";
  const SceneHash before = sceneHash(richScene());
  for (const SceneField& field : fields)
    for (std::size_t e = 0; e < field.edits.size(); ++e) {
      Scene s = richScene();
      field.edits[e](s);
      const SceneHash after = sceneHash(s);
      const std::string what = std::string("Scene::") + field.name + ", edit " + std::to_string(e);
      if (field.part) {
        EXPECT_NE(before.whole, after.whole) << what;
        EXPECT_EQ(changedParts(before, after), std::set<std::string>{field.part}) << what;
      } else {
        EXPECT_EQ(before.whole, after.whole) << what;
      }
    }
}

// The hash reads values, not memory: a copy in other allocations hashes the same, −0 as +0 and
// every NaN alike; its text is 16 hex digits for the whole and each part.
TEST(SceneHash, DeterministicAndValueBased) {
  const Scene base = richScene();
  const SceneHash h = sceneHash(base);
  std::vector<Scene> copies(3, base);  // distinct heap blocks for every array
  for (Scene& copy : copies) {
    copy.meshes.reserve(64);
    copy.lights.shrink_to_fit();
    EXPECT_EQ(sceneHash(copy).whole, h.whole);
    EXPECT_EQ(sceneHash(copy).parts, h.parts);
  }
  EXPECT_EQ(sceneContentHash(base), h.whole);
  for (const std::string& hex : {h.whole, h.parts[0], h.parts[4]}) {
    EXPECT_EQ(hex.size(), 16u);
    EXPECT_EQ(hex.find_first_not_of("0123456789abcdef"), std::string::npos) << hex;
  }
  std::set<std::string> distinct(h.parts.begin(), h.parts.end());
  EXPECT_EQ(distinct.size(), h.parts.size());

  Scene signedZero = base;
  signedZero.lights[0].irradiance = glm::vec3(-0.0f);
  EXPECT_EQ(sceneContentHash(signedZero), h.whole);
  Scene nanA = base, nanB = base;
  nanA.materials[0].emission.r = std::numeric_limits<float>::quiet_NaN();
  nanB.materials[0].emission.r = -std::numeric_limits<float>::signaling_NaN();
  EXPECT_EQ(sceneContentHash(nanA), sceneContentHash(nanB));
  EXPECT_NE(sceneContentHash(nanA), h.whole);
}

}  // namespace
