// The scene hash: whether a bake still matches a scene. GL-free.
//
// It covers every field of the scene model (scene/scene.h) that changes a bake, and nothing
// else:
//   meshes     positions, normals, both UV sets, indices, material index
//   materials  albedo, albedo texture index, emission, double-sided
//   textures   width, height, texels
//   instances  mobility, mesh index, transform (static instances only: bounce-bake bakes without
//              the dynamic ones, so the bake holds wherever they are placed: --move, the viewer)
//   lights     type, position, direction, intensity, irradiance, cone angles, baked-only
// Names, cameras, warnings and the source path are left out: renaming a node or adding a camera
// keeps the bake. The hash reads values, never bytes of a struct (no pointers, no padding); −0
// hashes as +0 and every NaN alike. Each part is hashed on its own (FNV-1a 64 over a
// little-endian serialisation, every array preceded by its length) so that a stale bake can say
// which part changed; the whole hash is FNV-1a over the five part hashes.
#pragma once

#include <array>
#include <string>

#include "scene/scene.h"

namespace bounce {

inline constexpr std::array<const char*, 5> kScenePartNames = {"meshes", "materials", "textures",
                                                               "instances", "lights"};

struct SceneHash {
  std::string whole;                                      // 16 hex digits (sceneContentHash)
  std::array<std::string, kScenePartNames.size()> parts;  // 16 hex digits each, in that order
};

SceneHash sceneHash(const Scene& scene);

// sceneHash(scene).whole: what bake.json's "sceneHash" holds.
std::string sceneContentHash(const Scene& scene);

}  // namespace bounce
