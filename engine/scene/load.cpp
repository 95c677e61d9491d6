#include "scene/load.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <system_error>

#include "scene/loaders.h"

namespace bounce {

Scene loadScene(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw LoadError(path, "file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw LoadError(path, "not a regular file");
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".gltf" && ext != ".glb" && ext != ".obj" && ext != ".json") {
    throw LoadError(path, "unsupported file extension '" + ext +
                              "' (expected .gltf, .glb, .obj or a .json wrapper)");
  }
  Scene scene;
  try {
    scene = ext == ".obj" ? loadObj(path) : ext == ".json" ? loadSceneJson(path) : loadGltf(path);
  } catch (const LoadError&) {
    throw;
  } catch (const std::exception& e) {  // e.g. std::bad_alloc on absurd sizes: still a LoadError
    throw LoadError(path, std::string("cannot load: ") + e.what());
  }
  scene.source = path.string();
  return scene;
}

}  // namespace bounce
