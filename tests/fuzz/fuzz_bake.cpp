// libFuzzer target: the bake-folder reader (engine/bake_folder/bake_folder.h). The input's first
// byte picks one file of a bake folder (0 bake.json, 1 layout.bin, 2 lightmap.exr, 3 vpls, 4
// visibility.bin, 5 error.exr; modulo 6), the rest of the input is that file's content; the others
// are those of tests/corpus/bake/valid.bake, a real bake of tests/corpus/bake/scene.gltf (one
// static area light, so it has a visibility.bin). bake.json records every file's size and hash; for
// a fuzzed file other than bake.json, the second bit of the first byte says whether bake.json
// records the fuzzed bytes (as a forger would, so the parsers and range checks behind the hash are
// reached) or keeps valid.bake's record (the hash check). Allowed outcomes: a Bake that the
// renderer can use blindly (lightmap size = layout size = bake.json's atlas size, irradiance finite
// in [0, kMaxBakeIrradiance]; one region per static instance with 3 UVs per triangle, UVs in [0,
// 1]; VPLs within ±kMaxBakeLength with unit normals and flux in [0, kMaxVplFlux], as many as
// bake.json says, its clamp distance in [0, kMaxBakeLength]; a visibility of the layout's size
// whose V are finite and in [0, 1] and whose lights are < the scene's static area-light count or
// one of the two marks), or a LoadError naming a file of the folder. Anything else aborts.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "fuzz_input_file.h"
#include "scene/area_lights.h"
#include "scene/load.h"

namespace {

namespace fs = std::filesystem;
constexpr int kFileCount = 6;
const char* const kFiles[kFileCount] = {"bake.json", "layout.bin",     "lightmap.exr",
                                        "vpls",      "visibility.bin", "error.exr"};

struct ValidBake {
  bounce::Scene scene;
  std::vector<char> files[kFileCount];
};

const ValidBake& valid() {
  static const ValidBake v = [] {
    const fs::path corpus = fs::path(BOUNCE_SOURCE_DIR) / "tests" / "corpus" / "bake";
    ValidBake out{bounce::loadScene(corpus / "scene.gltf"), {}};
    for (int i = 0; i < kFileCount; ++i) {
      std::ifstream in(corpus / "valid.bake" / kFiles[i], std::ios::binary);
      out.files[i].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      if (out.files[i].empty()) std::abort();  // the seed bake is missing: nothing to fuzz
    }
    return out;
  }();
  return v;
}

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_bake: %s\n", what.c_str());
  std::abort();
}

// The renderer indexes its static lights by these and scales their irradiance by V.
void checkVisibility(const bounce::BakedVisibility& visibility,
                     const bounce::LightmapLayout& layout, const bounce::Scene& scene) {
  if (visibility.width != layout.width || visibility.height != layout.height ||
      visibility.texels.size() !=
          static_cast<std::size_t>(layout.width) * static_cast<std::size_t>(layout.height))
    finding("visibility size disagrees with the layout");
  const std::size_t areaLights = bounce::sceneAreaLights(scene).staticCount();
  if (visibility.lightCount != areaLights) finding("visibility light count is not the scene's");
  if (visibility.punctualCount != scene.lights.size())
    finding("visibility punctual light count is not the scene's");
  // Indices name the static area lights, then the punctual ones (bake_folder/light_visibility.h).
  const std::size_t lights = areaLights + scene.lights.size();
  for (const bounce::TexelVisibility& texel : visibility.texels)
    for (int s = 0; s < bounce::kVisibilitySlots; ++s) {
      const uint16_t l = texel.light[s];
      if (l != bounce::kNoLight && l != bounce::kOtherLights && l >= lights)
        finding("visibility names a light index >= the static area and punctual lights");
      if (!std::isfinite(texel.visible[s]) || texel.visible[s] < 0.0f || texel.visible[s] > 1.0f)
        finding("visible fraction V not finite or outside [0, 1]");
    }
}

bool within(const glm::vec3& v, float limit) {
  return std::abs(v.x) <= limit && std::abs(v.y) <= limit && std::abs(v.z) <= limit;
}

void checkUsable(const bounce::Bake& bake, const bounce::Scene& scene) {
  const bounce::LightmapLayout& layout = bake.layout;
  if (bake.irradiance.width != layout.width || bake.irradiance.height != layout.height ||
      bake.irradiance.pixels.size() !=
          static_cast<std::size_t>(layout.width) * static_cast<std::size_t>(layout.height))
    finding("lightmap size disagrees with the layout");
  if (bake.manifest.atlas.width != layout.width || bake.manifest.atlas.height != layout.height)
    finding("bake.json's atlas size disagrees with the layout");
  for (const glm::vec3& e : bake.irradiance.pixels)
    if (!within(e, bounce::kMaxBakeIrradiance) || e.r < 0.0f || e.g < 0.0f || e.b < 0.0f)
      finding("irradiance not finite or outside [0, kMaxBakeIrradiance]");
  for (const bounce::InstanceLightmapUv& region : layout.instances) {
    if (region.instance >= scene.instances.size()) finding("region of a missing instance");
    const bounce::Instance& instance = scene.instances[region.instance];
    if (instance.mobility != bounce::Mobility::Static) finding("region of a dynamic instance");
    if (region.cornerUv.size() != 3 * scene.meshes.at(instance.mesh).triangleCount())
      finding("region corner count is not 3 per triangle");
    for (const glm::vec2& uv : region.cornerUv)
      if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f))
        finding("corner UV outside [0, 1]");
  }
  if (bake.vpls.has_value() != bake.manifest.vpls.has_value() ||
      (bake.vpls && bake.vpls->size() != bake.manifest.vpls->count))
    finding("VPLs disagree with bake.json");
  if (bake.manifest.vpls && !(bake.manifest.vpls->clampDistance >= 0.0 &&
                              bake.manifest.vpls->clampDistance <= bounce::kMaxBakeLength))
    finding("VPL clamp distance out of range");
  if (bake.vpls)
    for (const bounce::Vpl& v : *bake.vpls) {
      if (!within(v.position, bounce::kMaxBakeLength) || !within(v.from, bounce::kMaxBakeLength))
        finding("VPL position or path segment start not finite or beyond kMaxBakeLength");
      if (!within(v.flux, bounce::kMaxVplFlux) || v.flux.r < 0.0f || v.flux.g < 0.0f ||
          v.flux.b < 0.0f)
        finding("VPL flux negative, not finite or over kMaxVplFlux");
      if (std::abs(glm::length(v.normal) - 1.0f) > 1e-3f) finding("VPL normal not unit");
    }
  if (bake.vpls)
    for (std::size_t i = 1; i < bake.vpls->size(); ++i)
      if ((*bake.vpls)[i].path < (*bake.vpls)[i - 1].path) finding("VPL path indices decrease");
  if (bake.visibility) checkVisibility(*bake.visibility, layout, scene);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const ValidBake& v = valid();
  const int which = data[0] % kFileCount;
  const bool stamp = ((data[0] / kFileCount) & 1) == 0;
  const fs::path dir = bounce::fuzz::writeInput(data, 0, "unused").parent_path() / "f.bake";
  fs::create_directories(dir);
  std::string manifest(v.files[0].begin(), v.files[0].end());
  if (which != 0 && stamp) {
    bounce::BakeManifest m = bounce::parseManifest(dir / kFiles[0], manifest);
    m.files[kFiles[which]] = {size - 1, bounce::fnv1a64Hex({data + 1, size - 1})};
    manifest = bounce::manifestText(m);
  }
  for (int i = 0; i < kFileCount; ++i) {
    std::ofstream out(dir / kFiles[i], std::ios::binary | std::ios::trunc);
    if (i == which)
      out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    else if (i == 0)
      out.write(manifest.data(), static_cast<std::streamsize>(manifest.size()));
    else
      out.write(v.files[i].data(), static_cast<std::streamsize>(v.files[i].size()));
  }
  try {
    checkUsable(bounce::readBake(dir, v.scene), v.scene);
  } catch (const bounce::LoadError& e) {
    if (std::strstr(e.what(), dir.c_str()) == nullptr)
      finding(std::string("LoadError does not name a file of the folder: ") + e.what());
  }
  return 0;
}
