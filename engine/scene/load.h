// Scene loading: picks the loader by the file's extension (.gltf, .glb, .obj, or a .json wrapper
// that names a model file, its scale to metres, lights and a camera: scene_json_load.cpp).
// Every bad input throws LoadError naming the file and the reason; nothing crashes.
// Closed shells wound towards their unlit side are turned around (closed_shells.h), with a
// warning. Then static surfaces are split where other static geometry crosses them
// (crossing_cuts.h), so that no lightmap chart runs under a wall; scenes built in code call
// cutAtCrossings themselves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/load_error.h"
#include "scene/scene.h"

namespace bounce {

// What a caller can draw or bake at most, checked as soon as the file is read (before the
// shells and the crossing cuts, which take minutes on a million triangles).
struct SceneLimits {
  // Emissive triangles (scene/surface_rules.h): the renderer's emitter table holds one row per
  // triangle plus one per area light, GL_MAX_TEXTURE_SIZE rows (render/gpu_scene.h).
  std::size_t maxEmissiveTriangles = SIZE_MAX;
  std::string emissiveLimitReason;  // why, for the message
};

Scene loadScene(const std::filesystem::path& path, const SceneLimits& limits = {});

}  // namespace bounce
