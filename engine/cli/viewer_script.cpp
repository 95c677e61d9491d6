#include "cli/viewer_script.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/load_error.h"

namespace bounce {
namespace {

float parseNumber(const std::string& word, const std::string& what, const auto& fail) {
  std::size_t used = 0;
  float value = 0.0f;
  try {
    value = std::stof(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != word.size() || !std::isfinite(value))
    fail(what + " '" + word + "' is not a finite number");
  return value;
}

}  // namespace

std::vector<ScriptCommand> readViewerScript(const std::filesystem::path& file,
                                            const std::vector<std::string>& modes) {
  std::ifstream in(file);
  if (!in) throw LoadError(file, "cannot open the script");
  std::vector<ScriptCommand> commands;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const auto fail = [&](const std::string& why) {
      throw LoadError(file, "line " + std::to_string(line) + ": " + why);
    };
    if (const std::size_t hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    const auto arguments = [&](std::size_t n) {
      if (w.size() != n + 1)
        fail("'" + w[0] + "' takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s") +
             ", not " + std::to_string(w.size() - 1));
    };
    ScriptCommand c;
    c.line = line;
    if (w[0] == "camera") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Camera;
      c.text = w[1];
    } else if (w[0] == "view") {
      arguments(6);
      c.kind = ScriptCommand::Kind::View;
      for (int k = 0; k < 3; ++k) {
        c.position[k] = parseNumber(w[1 + k], "coordinate", fail);
        c.target[k] = parseNumber(w[4 + k], "coordinate", fail);
      }
      if (c.position == c.target) fail("'view' looks from a point at itself");
    } else if (w[0] == "mode") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Mode;
      if (std::find(modes.begin(), modes.end(), w[1]) == modes.end())
        fail("no render mode '" + w[1] + "'");
      c.text = w[1];
    } else if (w[0] == "exposure") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Exposure;
      c.number = parseNumber(w[1], "exposure", fail);
    } else if (w[0] == "panel") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Panel;
      if (w[1] != "on" && w[1] != "off") fail("'panel' takes on or off, not '" + w[1] + "'");
      c.on = w[1] == "on";
    } else if (w[0] == "frames") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Frames;
      const float n = parseNumber(w[1], "frame count", fail);
      if (n != std::floor(n) || n < 1.0f || n > 100000.0f)
        fail("frame count " + w[1] + " is not a whole number in [1, 100000]");
      c.count = static_cast<int>(n);
    } else if (w[0] == "capture" || w[0] == "window") {
      arguments(1);
      c.kind = w[0] == "capture" ? ScriptCommand::Kind::Capture : ScriptCommand::Kind::Window;
      const std::filesystem::path ext = std::filesystem::path(w[1]).extension();
      if (ext != ".png" && ext != ".exr") fail(w[1] + ": the file must end in .png or .exr");
      c.text = w[1];
    } else if (w[0] == "light") {
      arguments(5);
      c.kind = ScriptCommand::Kind::Light;
      c.text = w[1];
      c.field = w[2];
      if (c.field != "intensity" && c.field != "position" && c.field != "direction")
        fail("'light' sets intensity, position or direction, not '" + c.field + "'");
      for (int k = 0; k < 3; ++k) c.value[k] = parseNumber(w[3 + k], c.field, fail);
      if (c.field == "intensity" && (c.value.r < 0.0f || c.value.g < 0.0f || c.value.b < 0.0f))
        fail("a light's intensity is not negative");
      if (c.field == "direction" && c.value == glm::vec3(0.0f)) fail("a direction of length 0");
    } else if (w[0] == "bookmark") {
      arguments(2);
      if (w[1] != "save" && w[1] != "go") fail("'bookmark' takes save or go, not '" + w[1] + "'");
      c.kind = w[1] == "save" ? ScriptCommand::Kind::BookmarkSave : ScriptCommand::Kind::BookmarkGo;
      const float n = parseNumber(w[2], "bookmark", fail);
      if (n != std::floor(n) || n < 1.0f || n > static_cast<float>(kScriptBookmarks))
        fail("bookmark " + w[2] + " is not a whole number in [1, " +
             std::to_string(kScriptBookmarks) + "]");
      c.count = static_cast<int>(n);
    } else if (w[0] == "vpl-paths") {
      arguments(1);
      c.kind = ScriptCommand::Kind::VplPaths;
      const float n = parseNumber(w[1], "light path count", fail);
      if (n != std::floor(n) || n < 1.0f || n > 1e9f)
        fail("light path count " + w[1] + " is not a whole number in [1, 1e9]");
      c.count = static_cast<int>(n);
    } else if (w[0] == "vpl-clamp") {
      arguments(1);
      c.kind = ScriptCommand::Kind::VplClamp;
      c.number = parseNumber(w[1], "clamp distance", fail);
      if (c.number < 0.0f) fail("a clamp distance is not negative");
    } else if (w[0] == "reference") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Reference;
      if (std::filesystem::path(w[1]).extension() != ".exr")
        fail(w[1] + ": a reference is an EXR file (.exr)");
      c.text = w[1];
    } else if (w[0] == "compare") {
      arguments(1);
      c.kind = ScriptCommand::Kind::Compare;
      if (w[1] != "off" && w[1] != "split" && w[1] != "difference")
        fail("'compare' takes off, split or difference, not '" + w[1] + "'");
      c.text = w[1];
    } else if (w[0] == "rebake" || w[0] == "wait-bake" || w[0] == "cancel-bake") {
      arguments(0);
      c.kind = w[0] == "rebake"      ? ScriptCommand::Kind::Rebake
               : w[0] == "wait-bake" ? ScriptCommand::Kind::WaitBake
                                     : ScriptCommand::Kind::CancelBake;
    } else {
      fail("unknown command '" + w[0] +
           "' (camera, view, mode, exposure, panel, frames, capture, window, light, rebake, "
           "wait-bake, cancel-bake, bookmark, vpl-paths, vpl-clamp, reference, compare)");
    }
    commands.push_back(c);
  }
  if (commands.empty()) throw LoadError(file, "the script has no commands");
  return commands;
}

}  // namespace bounce
