// Runs every file of tests/corpus (manifest.tsv, written by make_corpus.py) through the real
// loaders: bad files must give one error naming the file and containing the manifest's reason;
// good ones must load with the stated properties. Also a few through the tools (exit status
// and message). One CTest per file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "image/image_io.h"
#include "scene/load.h"
#include "support/scene_invariants.h"
#include "support/tool_run.h"

namespace bounce {
namespace {

namespace fs = std::filesystem;
const fs::path kCorpus = fs::path(BOUNCE_SOURCE_DIR) / "tests" / "corpus";

struct Entry {
  std::string file;    // relative to tests/corpus
  std::string expect;  // "ok" or "error"
  std::string detail;  // properties (ok) or the reason substring (error)
};

void PrintTo(const Entry& e, std::ostream* out) {
  *out << e.file << " (" << e.expect << ": " << e.detail << ")";
}

std::vector<Entry> manifest() {
  std::vector<Entry> entries;
  std::ifstream in(kCorpus / "manifest.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Entry e;
    std::getline(fields, e.file, '\t');
    std::getline(fields, e.expect, '\t');
    std::getline(fields, e.detail);
    entries.push_back(e);
  }
  return entries;
}

std::map<std::string, long> properties(const std::string& detail) {
  std::map<std::string, long> out;
  std::istringstream in(detail);
  std::string item;
  while (std::getline(in, item, ';')) {
    const std::size_t eq = item.find('=');
    if (eq != std::string::npos) out[item.substr(0, eq)] = std::stol(item.substr(eq + 1));
  }
  return out;
}

class Corpus : public ::testing::TestWithParam<Entry> {};

TEST_P(Corpus, LoadsOrFailsAsTheManifestSays) {
  const Entry& e = GetParam();
  const fs::path path = kCorpus / e.file;
  const bool exr = path.extension() == ".exr";
  const bool bakeFolder = path.extension() == ".bake";
  try {
    const auto props = properties(e.detail);
    auto expectProperty = [&](const std::string& key, std::size_t value) {
      if (props.count(key)) {
        EXPECT_EQ(static_cast<long>(value), props.at(key)) << key;
      }
    };
    if (bakeFolder) {  // against the scene it was baked for
      const Scene scene = loadScene(kCorpus / "bake" / "scene.gltf");
      const Bake bake = readBake(path, scene);
      expectProperty("width", static_cast<std::size_t>(bake.irradiance.width));
      expectProperty("height", static_cast<std::size_t>(bake.irradiance.height));
      expectProperty("vpls", bake.vpls ? bake.vpls->size() : 0);
      expectProperty("vislights", bake.visibility ? bake.visibility->lightCount : 0);
    } else if (exr) {
      const Image image = readExr(path);
      std::size_t nonFinite = 0;
      for (const glm::vec3& p : image.pixels)
        nonFinite += std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) ? 0 : 1;
      expectProperty("width", static_cast<std::size_t>(image.width));
      expectProperty("height", static_cast<std::size_t>(image.height));
      expectProperty("nonfinite", nonFinite);
    } else {
      const Scene scene = loadScene(path);
      EXPECT_EQ(test::brokenInvariant(scene), "");
      expectProperty("triangles", scene.triangleCount());
      expectProperty("lights", scene.lights.size());
      expectProperty("cameras", scene.cameras.size());
      expectProperty("textures", scene.textures.size());
    }
    EXPECT_EQ(e.expect, "ok") << path << " loaded; expected an error containing '" << e.detail
                              << "'";
  } catch (const std::runtime_error& error) {  // LoadError, or the image readers' errors
    const std::string message = error.what();
    EXPECT_EQ(e.expect, "error") << message;
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    if (e.expect == "error") {
      EXPECT_NE(message.find(e.detail), std::string::npos)
          << "expected '" << e.detail << "' in: " << message;
    }
  }
}

std::string testName(const ::testing::TestParamInfo<Entry>& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Files, Corpus, ::testing::ValuesIn(manifest()), testName);

// A few corpus files through the tools as a user runs them: exit status 1 and one message
// naming the file and the reason; and no output file.
struct ToolCase {
  const char* name;
  const char* command;  // {tool}, {corpus} and {out} are replaced
  const char* message;
};

void PrintTo(const ToolCase& c, std::ostream* out) {
  *out << c.name;
}

class CorpusTools : public ::testing::TestWithParam<ToolCase> {};

TEST_P(CorpusTools, FailWithTheFileAndTheReason) {
  const ToolCase& c = GetParam();
  const fs::path dir = fs::temp_directory_path() /
                       ("bounce-corpus-tools-" + std::string(c.name) + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string command = c.command;
  auto replace = [&](const std::string& key, const std::string& value) {
    for (std::size_t at; (at = command.find(key)) != std::string::npos;)
      command.replace(at, key.size(), value);
  };
  replace("{tool}", std::string(BOUNCE_BIN_DIR) + "/");
  replace("{corpus}", kCorpus.string() + "/");
  replace("{out}", (dir / "out").string());
  const test::ToolRun run = test::runCommand(command, dir / "log");
  const std::string& log = run.output;
  EXPECT_EQ(run.exitCode, 1) << command << "\n" << log;
  EXPECT_NE(log.find(c.message), std::string::npos) << command << "\n" << log;
  int files = 0;
  for ([[maybe_unused]] const auto& f : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1) << "an output was written";  // only the log
  fs::remove_all(dir);
}

const ToolCase kToolCases[] = {
    {"render_texture",
     "{tool}bounce-render {corpus}gltf/texture_17000x1.gltf --width 8 --height 8 --out {out}.png",
     "texture_17000x1.gltf: invalid glTF: image 0 '../png/wide_17000x1.png': image of 17000x1 "
     "texels exceeds"},
    {"render_light",
     "{tool}bounce-render {corpus}gltf/value_point_1e40_cd.gltf --width 8 --height 8 --out "
     "{out}.exr",
     "value_point_1e40_cd.gltf: node 0 'tri': light intensity W/sr"},
    {"render_obj_noise", "{tool}bounce-render {corpus}obj/random_64k.obj --out {out}.png",
     "random_64k.obj: line 1: binary data"},
    {"trace_depth",
     "{tool}bounce-trace {corpus}gltf/depth_100000.gltf --width 4 --height 4 --spp 1 --out "
     "{out}.exr",
     "depth_100000.gltf: JSON nests arrays/objects deeper than 64 levels"},
    {"trace_obj_nan",
     "{tool}bounce-trace {corpus}obj/v_nan.obj --width 4 --height 4 --spp 1 --out {out}.exr",
     "v_nan.obj: line 1: 'nan' in 'v' is not a finite number"},
    {"trace_far",
     "{tool}bounce-trace {corpus}gltf/value_translation_5e9.gltf --width 4 --height 4 --spp 1 "
     "--out {out}.exr",
     "beyond bounce's coordinate limit of 1e6 m"},
    {"compare_uint",
     "{tool}bounce-compare {corpus}exr/uint_channels.exr {corpus}exr/ok_float_2x2.exr",
     "uint_channels.exr: cannot read EXR: channel 'B' holds UINT values"},
    {"compare_truncated",
     "{tool}bounce-compare {corpus}exr/ok_float_2x2.exr {corpus}exr/truncated_pixels.exr",
     "truncated_pixels.exr: cannot read EXR"},
};

std::string toolCaseName(const ::testing::TestParamInfo<ToolCase>& param) {
  return param.param.name;
}

INSTANTIATE_TEST_SUITE_P(Tools, CorpusTools, ::testing::ValuesIn(kToolCases), toolCaseName);

}  // namespace
}  // namespace bounce
