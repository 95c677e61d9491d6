// The per-format loaders behind loadScene (load.h). Internal to bounce_scene.
#pragma once

#include <filesystem>

#include "scene/scene.h"

namespace bounce {

// The scene as its file describes it, picked by extension (loadScene then orients its closed
// shells, closed_shells.h). Throws LoadError.
Scene loadSceneAsWritten(const std::filesystem::path& path);
// glTF 2.0, text (.gltf) or binary (.glb). Throws LoadError.
Scene loadGltf(const std::filesystem::path& path);
// Wavefront OBJ with its MTL materials. Throws LoadError.
Scene loadObj(const std::filesystem::path& path);
// A wrapper (.json) naming one model file by path, its scale to metres, lights and a camera
// (format in scene_json_load.cpp). Throws LoadError.
Scene loadSceneJson(const std::filesystem::path& path);

}  // namespace bounce
