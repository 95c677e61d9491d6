#include "scene/load.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <string>
#include <system_error>

#include "scene/area_lights.h"
#include "scene/closed_shells.h"
#include "scene/crossing_cuts.h"
#include "scene/loaders.h"

namespace bounce {

Scene loadSceneAsWritten(const std::filesystem::path& path) {
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

Scene loadScene(const std::filesystem::path& path, const SceneLimits& limits) {
  Scene scene = loadSceneAsWritten(path);
  if (limits.maxEmissiveTriangles != SIZE_MAX) {
    const std::size_t emissive = emitterTriangles(scene).size();
    if (emissive > limits.maxEmissiveTriangles)
      throw LoadError(path, std::to_string(emissive) + " emissive triangles, more than the " +
                                std::to_string(limits.maxEmissiveTriangles) + " allowed (" +
                                limits.emissiveLimitReason + ")");
  }
  if (const ShellOrientation shells = orientClosedShells(scene); shells.turned > 0)
    scene.warnings.push_back(
        std::to_string(shells.turned) + " of " + std::to_string(shells.closedShells) +
        " closed shells had triangles wound towards their unlit side (every light source is on "
        "the other side): turned, so that the renderer draws and the lightmap holds the lit side");
  // After the shells are turned: the cut edges are numbered by the final corner order.
  cutAtCrossings(scene);
  return scene;
}

}  // namespace bounce
