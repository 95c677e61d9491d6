#include "pipeline/scene_bake_settings.h"

#include <stdexcept>
#include <string>

#include "atlas/texel_density.h"
#include "bake/lightmap_bake.h"
#include "vpl/vpl_generate.h"

namespace bounce {

SceneBakeSettings::SceneBakeSettings() {
  const LightmapBakeSettings defaults = defaultBakeSettings();
  maxTexels = kDefaultMaxTexels;
  spp = defaults.irradiance.maxSpp;
  targetError = defaults.irradiance.targetError;
  maxDepth = defaults.irradiance.maxDepth;
  denoise = defaults.denoise;
  vpls = VplSettings{}.maxVpls;
  vplError = VplSettings{}.relativeError;
}

nlohmann::json bakeInputsJson(const SceneBakeSettings& s) {
  return {{"texelSize", s.texelSize},
          {"texelBudget", s.texelBudget},
          {"maxTexels", s.maxTexels},
          {"spp", s.spp},
          {"targetError", s.targetError},
          {"maxDepth", s.maxDepth},
          {"seed", s.seed},
          {"lightChoice", s.lightChoice == LightChoice::ByPlace ? "place" : "power"},
          {"backend", s.backend == RayBackend::Embree ? "embree" : "bvh"},
          {"denoise", s.denoise},
          {"vpls", s.vpls},
          {"vplError", s.vplError},
          {"tileSize", s.tileSize}};
}

SceneBakeSettings bakeSettingsFromInputs(const nlohmann::json& inputs, SceneBakeSettings s) {
  const auto get = [&](const char* name, auto& field) {
    const auto it = inputs.find(name);
    try {
      if (it == inputs.end()) throw std::runtime_error("missing");
      field = it->get<std::remove_reference_t<decltype(field)>>();
    } catch (const std::exception&) {
      throw std::runtime_error(std::string("the bake inputs' \"") + name +
                               "\" is missing or of the wrong type");
    }
  };
  if (!inputs.is_object()) throw std::runtime_error("the bake inputs are not a JSON object");
  std::string backend;
  get("texelSize", s.texelSize);
  get("texelBudget", s.texelBudget);
  get("maxTexels", s.maxTexels);
  get("spp", s.spp);
  get("targetError", s.targetError);
  get("maxDepth", s.maxDepth);
  get("seed", s.seed);
  get("backend", backend);
  get("denoise", s.denoise);
  get("vpls", s.vpls);
  get("vplError", s.vplError);
  get("tileSize", s.tileSize);
  s.backend = parseRayBackend(backend);
  std::string choice = "power";
  if (inputs.contains("lightChoice")) get("lightChoice", choice);
  if (choice != "place" && choice != "power")
    throw std::runtime_error("the bake inputs' \"lightChoice\" is \"" + choice +
                             "\", not \"place\" or \"power\"");
  s.lightChoice = choice == "place" ? LightChoice::ByPlace : LightChoice::ByPower;
  return s;
}

}  // namespace bounce
