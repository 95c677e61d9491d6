#include "bake_folder/bake_settings.h"

#include <limits>

#include <nlohmann/json.hpp>

#include "bake_folder/bake_manifest.h"
#include "bake_folder/gather.h"
#include "bake_folder/json_fields.h"

namespace bounce {
namespace {

constexpr int64_t kIntMax = std::numeric_limits<int>::max();
constexpr double kFloatMax = std::numeric_limits<float>::max();

}  // namespace

nlohmann::json bakeSettingsJson(const BakeSettings& s) {
  // Reals as doubles: the float's exact value, which a parse turns back into the same float.
  nlohmann::json json = {{"texelSize", static_cast<double>(s.texelSize)},
                         {"texelBudget", s.texelBudget},
                         {"maxTexels", s.maxTexels},
                         {"maxSpp", s.maxSpp},
                         {"targetError", static_cast<double>(s.targetError)},
                         {"maxDepth", s.maxDepth},
                         {"seed", s.seed},
                         {"denoise", s.denoise},
                         {"lightChoice", lightChoiceName(s.lightChoice)},
                         {"pointsPerTexel", s.pointsPerTexel},
                         {"vpls", s.vpls},
                         {"vplError", static_cast<double>(s.vplError)}};
  // Only a cache gather names it: a paths bake keeps the hash it had before the option existed.
  if (s.gather == Gather::Cache) {
    json["gather"] = gatherName(s.gather);
    json["cacheSpp"] = s.cacheSpp;
  }
  if (s.errorFloor > 0.0f) json["errorFloor"] = static_cast<double>(s.errorFloor);
  return json;
}

BakeSettings parseBakeSettings(const std::filesystem::path& file, const nlohmann::json& object,
                               const std::string& path) {
  const JsonFields f(file, object, path);
  BakeSettings s;
  s.texelSize = static_cast<float>(f.real("texelSize", 0.0, kMaxBakeLength));
  s.texelBudget = static_cast<int>(f.integer("texelBudget", 0, kIntMax));
  s.maxTexels = f.integer("maxTexels", 0, std::numeric_limits<int64_t>::max());
  s.maxSpp = static_cast<int>(f.integer("maxSpp", 0, kIntMax));
  s.targetError = static_cast<float>(f.real("targetError", 0.0, kFloatMax));
  s.maxDepth = static_cast<int>(f.integer("maxDepth", 0, kIntMax));
  s.seed = static_cast<uint32_t>(f.integer("seed", 0, UINT32_MAX));
  s.denoise = f.boolean("denoise");
  // Settings written before the pick existed mean "power", the only pick then.
  const std::string choice = f.find("lightChoice") ? f.text("lightChoice") : "power";
  const std::optional<LightChoice> parsed = parseLightChoice(choice);
  if (!parsed)
    f.fail(f.name("lightChoice") + " is \"" + choice + "\", not " +
           lightChoiceName(LightChoice::ByPlace) + " or " + lightChoiceName(LightChoice::ByPower));
  s.lightChoice = *parsed;
  s.pointsPerTexel = static_cast<int>(f.integer("pointsPerTexel", 0, kIntMax));
  s.vpls = static_cast<int>(f.integer("vpls", 0, kIntMax));
  s.vplError = static_cast<float>(f.real("vplError", 0.0, kFloatMax));
  // Settings written before the gather existed, and every paths bake, mean "paths".
  const std::string gather = f.find("gather") ? f.text("gather") : "paths";
  const std::optional<Gather> parsedGather = parseGather(gather);
  if (!parsedGather)
    f.fail(f.name("gather") + " is \"" + gather + "\", not " + gatherName(Gather::Paths) + " or " +
           gatherName(Gather::Cache));
  s.gather = *parsedGather;
  if (s.gather == Gather::Cache) s.cacheSpp = static_cast<int>(f.integer("cacheSpp", 1, kIntMax));
  // Absent in every bake without a floor.
  if (f.find("errorFloor")) s.errorFloor = static_cast<float>(f.real("errorFloor", 0.0, kFloatMax));
  return s;
}

std::string settingsHash(const BakeSettings& settings) {
  const std::string text = bakeSettingsJson(settings).dump();
  return fnv1a64Hex({reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

std::string settingsHashWithoutLightChoice(const BakeSettings& settings) {
  nlohmann::json json = bakeSettingsJson(settings);
  json.erase("lightChoice");
  const std::string text = json.dump();
  return fnv1a64Hex({reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

}  // namespace bounce
