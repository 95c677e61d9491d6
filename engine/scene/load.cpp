#include "scene/load.h"

#include <algorithm>
#include <cctype>
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
  Scene scene;
  if (ext == ".gltf" || ext == ".glb") {
    scene = loadGltf(path);
  } else if (ext == ".obj") {
    scene = loadObj(path);
  } else {
    throw LoadError(path,
                    "unsupported file extension '" + ext + "' (expected .gltf, .glb or .obj)");
  }
  scene.source = path.string();
  return scene;
}

}  // namespace bounce
