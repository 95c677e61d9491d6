// Scene loading: picks the loader by the file's extension (.gltf, .glb, .obj).
// Every bad input throws LoadError naming the file and the reason; nothing crashes.
#pragma once

#include <filesystem>

#include "scene/load_error.h"
#include "scene/scene.h"

namespace bounce {

Scene loadScene(const std::filesystem::path& path);

}  // namespace bounce
