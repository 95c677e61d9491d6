// The scene model shared by the renderer and the baker. GL-free, plain data.
//
// Units (per linear-RGB channel):
//   lengths in metres; angles in radians;
//   Material::emission is radiance in W/(sr·m²) (Lambertian emitter, emits on the front face);
//   Material::albedo is the diffuse reflectance ρ in [0,1] (BRDF ρ/π);
//   point/spot intensity in W/sr; directional irradiance in W/m² on a surface facing the light.
// Photometric inputs (glTF cd, lux) are converted once, on load (see units.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace bounce {

// A texture of linear-RGB values, rows top to bottom (glTF/OBJ convention: uv (0,0) is the
// top-left texel). sRGB-encoded files are decoded to linear on load.
struct Texture {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> texels;  // width*height, row-major, top row first
};

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};                 // diffuse reflectance ρ, linear RGB
  std::optional<uint32_t> albedoTexture;  // index into Scene::textures, multiplies albedo
  glm::vec3 emission{0.0f};               // emitted radiance, W/(sr·m²)
  bool doubleSided = false;               // emission and shading on both faces
  // Baked only (glTF material extras.bounce.bake = "all"): an emissive material's direct light
  // is baked into the lightmap with its indirect light, and the renderer does not draw it live
  // once a bake is attached (as Light::bakeDirect for punctual lights).
  bool bakeDirect = false;

  // True when emittedRadiance(*this) (scene/surface_rules.h) is positive in some channel.
  bool isEmissive() const;
};

// An indexed triangle mesh in its own object space. Counter-clockwise triangles face the
// side their geometric normal points to.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // metres
  std::vector<glm::vec3>
      normals;                    // unit shading normals, one per position (never empty after load)
  std::vector<glm::vec2> uv0;     // material UVs; empty when the source has none
  std::vector<glm::vec2> uv1;     // lightmap UVs (unique, non-overlapping); empty until unwrapped
  std::vector<uint32_t> indices;  // 3 per triangle
  uint32_t material = 0;          // index into Scene::materials
  // Where other static geometry crosses this surface (scene/crossing_cuts.h): one byte per
  // triangle, or empty when nothing does. Bit k (k = 0, 1, 2): the edge from corner k to corner
  // (k + 1) mod 3 bounds a lightmap chart. Bit k + 3: another surface meets or passes through
  // this one along that edge, so its two sides see different light and no filter joins them.
  std::vector<uint8_t> cutEdges;

  std::size_t triangleCount() const { return indices.size() / 3; }
};

enum class Mobility : uint8_t {
  Static,   // lightmapped: its indirect light comes from the baked lightmap
  Dynamic,  // moves at run time: its indirect light comes from VPLs
};

// One placement of a mesh; glTF node hierarchies are flattened into world transforms.
struct Instance {
  std::string name;
  uint32_t mesh = 0;          // index into Scene::meshes
  glm::mat4 transform{1.0f};  // object to world
  Mobility mobility = Mobility::Static;
  // Lightmap texels per metre relative to the scene's density (glTF extras.bounce.lightmapScale,
  // inherited by child nodes): 2 gives texels half as wide, 4× as many per m². In [0, 64]; 0
  // gives it no lightmap: its baked light comes from irradiance probes around it (the
  // atlas does the same for an instance under kMinLightmapTexels, atlas/atlas.h).
  float lightmapScale = 1.0f;
};

enum class LightType : uint8_t { Point, Spot, Directional };

// A punctual light. Area lights are not here: they are emissive meshes (Material::emission).
struct Light {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 position{0.0f};       // world, metres (point, spot)
  glm::vec3 direction{0, -1, 0};  // world unit vector the light travels along (spot, directional)
  glm::vec3 intensity{0.0f};      // W/sr (point, spot)
  glm::vec3 irradiance{0.0f};     // W/m² at normal incidence (directional)
  float innerConeAngle = 0.0f;    // spot: full intensity inside this half-angle, radians
  float outerConeAngle = 0.7853982f;  // spot: zero outside this half-angle, radians
  // Baked only (glTF extras.bounce.bake = "all"): its direct light is baked into the lightmap
  // with its indirect light, and the renderer does not draw it live. Otherwise (the default) the
  // lightmap holds only its indirect light.
  bool bakeDirect = false;
  // glTF node extras.bounce.mobility (inherited from the parent node; default static). A static
  // light does not move: the bake holds its visibility per lightmap texel (shadows of the static
  // scene, bake_folder/light_visibility.h) and its indirect light. A dynamic one may move: it is
  // shadowed by shadow maps alone and the bake holds none of its light (the lightmap would be
  // wrong once it moved), as Unreal's movable lights.
  Mobility mobility = Mobility::Static;
  // glTF's `range` is ignored: bounce's lights follow the inverse-square law without cut-off.
};

// A pinhole camera looking down its local −Z axis with +Y up (the glTF convention).
struct Camera {
  std::string name;
  // Rigid: a rotation (orthonormal columns, determinant +1) plus the translation. Loaders strip
  // a node's scale and shear, so znear/zfar stay metres in the world.
  glm::mat4 cameraToWorld{1.0f};
  float yfov = 0.6859f;  // full vertical field of view, radians
  float aspect = 0.0f;   // width/height; 0 means "take it from the image size"
  float znear = 0.01f;   // metres
  float zfar = 1000.0f;  // metres

  glm::vec3 position() const { return glm::vec3(cameraToWorld[3]); }
  glm::vec3 forward() const { return -glm::normalize(glm::vec3(cameraToWorld[2])); }
  glm::vec3 up() const { return glm::normalize(glm::vec3(cameraToWorld[1])); }
};

struct Scene {
  std::string source;  // the file it was loaded from, for messages
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Instance> instances;
  std::vector<Light> lights;
  std::vector<Camera> cameras;
  // What the loader could not represent (e.g. an ignored emissiveTexture), one sentence each,
  // for the tools to print.
  std::vector<std::string> warnings;

  std::size_t triangleCount() const;
  // Index of the camera called `name`; throws std::invalid_argument naming the known cameras.
  std::size_t findCamera(const std::string& name) const;
};

}  // namespace bounce
