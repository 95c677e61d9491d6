#include "pipeline/scene_bake_settings.h"

#include <limits>

#include <nlohmann/json.hpp>

#include "atlas/texel_density.h"
#include "bake/lightmap_bake.h"
#include "bake_folder/json_fields.h"
#include "ray/ray_kernel.h"
#include "vpl/vpl_generate.h"

namespace bounce {

SceneBakeSettings::SceneBakeSettings() : backend(RayBackend::Embree) {
  const LightmapBakeSettings defaults = defaultBakeSettings();
  maxTexels = kDefaultMaxTexels;
  maxSpp = defaults.irradiance.maxSpp;
  targetError = defaults.irradiance.targetError;
  maxDepth = defaults.irradiance.maxDepth;
  denoise = defaults.denoise;
  gather = defaults.gather;
  cacheSpp = defaults.cacheSpp;
  errorFloor = defaults.errorFloor;
  pointsPerTexel = defaults.pointsPerTexel;
  vpls = VplSettings{}.maxVpls;
  vplError = VplSettings{}.relativeError;
}

nlohmann::json bakeInputsJson(const SceneBakeSettings& s) {
  nlohmann::json inputs = bakeSettingsJson(s);
  inputs["backend"] = s.backend == RayBackend::Embree ? "embree" : "bvh";
  inputs["tileSize"] = s.tileSize;
  return inputs;
}

SceneBakeSettings bakeSettingsFromInputs(const std::filesystem::path& file,
                                         const nlohmann::json& inputs) {
  if (!inputs.is_object()) throw LoadError(file, "the bake inputs are not a JSON object");
  SceneBakeSettings s;
  static_cast<BakeSettings&>(s) = parseBakeSettings(file, inputs, "");
  const JsonFields f(file, inputs, "");
  try {
    s.backend = parseRayBackend(f.text("backend"));
  } catch (const std::invalid_argument& e) {
    f.fail(e.what());
  }
  s.tileSize = static_cast<int>(f.integer("tileSize", 1, std::numeric_limits<int>::max()));
  return s;
}

}  // namespace bounce
