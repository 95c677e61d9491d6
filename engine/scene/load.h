// Scene loading: picks the loader by the file's extension (.gltf, .glb, .obj, or a .json wrapper
// that names a model file, its scale to metres, lights and a camera: scene_json_load.cpp).
// Every bad input throws LoadError naming the file and the reason; nothing crashes.
// Closed shells wound towards their unlit side are turned around (closed_shells.h), with a
// warning. Then static surfaces are split where other static geometry crosses them
// (crossing_cuts.h), so that no lightmap chart runs under a wall; scenes built in code call
// cutAtCrossings themselves.
#pragma once

#include <filesystem>

#include "scene/load_error.h"
#include "scene/scene.h"

namespace bounce {

Scene loadScene(const std::filesystem::path& path);

}  // namespace bounce
