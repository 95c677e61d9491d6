// The bake's settings schema (bake_folder/bake_settings.h): bake.json and the tile journal's key
// write it with one codec, so every field must come back bit for bit from its text (a resume or
// a merge bakes with the floats the first bake used), and a field missing or out of range is
// refused with its name.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "bake_folder/bake_settings.h"
#include "bake_folder/gather.h"
#include "io/load_error.h"

using namespace bounce;

namespace {

TEST(BakeSettingsJson, EveryFieldComesBackBitForBitFromItsText) {
  BakeSettings s;
  s.texelSize = 0.1f;  // no float is 0.1: the text must name the float's own value
  s.texelBudget = 12345;
  s.maxTexels = int64_t{1} << 40;
  s.maxSpp = 777;
  s.targetError = 0.037f;
  s.maxDepth = 9;
  s.seed = 0xfffffffeu;
  s.denoise = true;
  s.lightChoice = LightChoice::ByPower;
  s.pointsPerTexel = 5;
  s.vpls = 4321;
  s.vplError = 0.0123f;
  const nlohmann::json text = nlohmann::json::parse(bakeSettingsJson(s).dump());
  const BakeSettings back = parseBakeSettings("key", text, "settings");
  EXPECT_EQ(back.texelSize, s.texelSize);
  EXPECT_EQ(back.texelBudget, s.texelBudget);
  EXPECT_EQ(back.maxTexels, s.maxTexels);
  EXPECT_EQ(back.maxSpp, s.maxSpp);
  EXPECT_EQ(back.targetError, s.targetError);
  EXPECT_EQ(back.maxDepth, s.maxDepth);
  EXPECT_EQ(back.seed, s.seed);
  EXPECT_EQ(back.denoise, s.denoise);
  EXPECT_EQ(back.lightChoice, s.lightChoice);
  EXPECT_EQ(back.pointsPerTexel, s.pointsPerTexel);
  EXPECT_EQ(back.vpls, s.vpls);
  EXPECT_EQ(back.vplError, s.vplError);
  EXPECT_EQ(settingsHash(back), settingsHash(s));
  EXPECT_EQ(text.size(), 12u);  // one key per field, nothing else

  nlohmann::json old = text;  // written before the light pick existed: "power", the only one
  old.erase("lightChoice");
  EXPECT_EQ(parseBakeSettings("key", old, "settings").lightChoice, LightChoice::ByPower);
}

// The gather (bake_folder/gather.h): a cache bake names it and its cache's samples, so its hash
// differs from the paths bake's; a paths bake writes neither key, so the settings and hash of
// every bake written before the option existed stay what they were.
TEST(BakeSettingsJson, TheCacheGatherIsNamedAndChangesTheHashAPathsBakeIsUnchanged) {
  BakeSettings paths;
  paths.maxSpp = 4096;
  const nlohmann::json before = bakeSettingsJson(paths);
  EXPECT_FALSE(before.contains("gather"));
  EXPECT_FALSE(before.contains("cacheSpp"));
  EXPECT_EQ(parseBakeSettings("key", before, "settings").gather, Gather::Paths);
  BakeSettings cache = paths;
  cache.gather = Gather::Cache;
  cache.cacheSpp = 48;
  const nlohmann::json text = nlohmann::json::parse(bakeSettingsJson(cache).dump());
  EXPECT_EQ(text.value("gather", ""), "cache");
  const BakeSettings back = parseBakeSettings("key", text, "settings");
  EXPECT_EQ(back.gather, Gather::Cache);
  EXPECT_EQ(back.cacheSpp, 48);
  EXPECT_EQ(settingsHash(back), settingsHash(cache));
  EXPECT_NE(settingsHash(cache), settingsHash(paths));
  cache.cacheSpp = 64;
  EXPECT_NE(settingsHash(cache), settingsHash(back));
}

TEST(BakeSettingsJson, AFieldMissingOrOutOfRangeIsNamed) {
  const nlohmann::json good = bakeSettingsJson(BakeSettings{});
  const auto refusal = [](const nlohmann::json& j) {
    try {
      parseBakeSettings("bake.json", j, "settings");
    } catch (const LoadError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  nlohmann::json missing = good;
  missing.erase("maxSpp");
  EXPECT_NE(refusal(missing).find("\"settings.maxSpp\""), std::string::npos) << refusal(missing);
  nlohmann::json big = good;
  big["texelBudget"] = int64_t{1} << 40;  // over an int
  EXPECT_NE(refusal(big).find("\"settings.texelBudget\" is 1099511627776, out of range"),
            std::string::npos)
      << refusal(big);
  nlohmann::json choice = good;
  choice["lightChoice"] = "brightest";
  EXPECT_NE(refusal(choice).find("settings.lightChoice is \"brightest\", not place or power"),
            std::string::npos)
      << refusal(choice);
  nlohmann::json gather = good;
  gather["gather"] = "photons";
  EXPECT_NE(refusal(gather).find("settings.gather is \"photons\", not paths or cache"),
            std::string::npos)
      << refusal(gather);
  gather["gather"] = "cache";
  EXPECT_NE(refusal(gather).find("\"settings.cacheSpp\""), std::string::npos) << refusal(gather);
}

}  // namespace
