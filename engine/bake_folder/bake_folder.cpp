#include "bake_folder/bake_folder.h"

#include <fcntl.h>   // AT_FDCWD
#include <signal.h>  // kill(pid, 0): is the process alive
#include <stdio.h>   // renameat2, RENAME_EXCHANGE (glibc ≥ 2.28)
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "bake_folder/bake_input_file.h"
#include "bake_folder/manifest_rules.h"
#include "bake_folder/probe_file.h"
#include "bake_folder/visibility_file.h"
#include "bake_folder/vpl_file.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "io/byte_stream.h"
#include "io/load_error.h"
#include "scene/area_lights.h"

namespace bounce {
namespace fs = std::filesystem;
namespace {

constexpr char kManifestName[] = "bake.json";
constexpr char kLightmapName[] = "lightmap.exr";
constexpr char kErrorMapName[] = "error.exr";
constexpr char kLayoutName[] = "layout.bin";

// layout.bin, all values little-endian, no padding:
//   char[8] magic "BNCLMLAY" | u32 version (= kBakeFormatVersion)
//   i32 width | i32 height | f32 texelSize (m) | i32 padding | i32 chartCount | f32 utilisation
//   u32 instanceCount, then per instance: u32 instance | u32 cornerCount | cornerCount × (f32 u,
//   f32 v)
// and nothing after the last instance.
constexpr char kLayoutMagic[8] = {'B', 'N', 'C', 'L', 'M', 'L', 'A', 'Y'};

std::vector<unsigned char> encodeLayout(const LightmapLayout& layout) {
  ByteWriter w;
  w.raw(kLayoutMagic, sizeof kLayoutMagic);
  w.u32(kBakeFormatVersion);
  w.i32(layout.width);
  w.i32(layout.height);
  w.f32(layout.texelSize);
  w.i32(layout.padding);
  w.i32(layout.chartCount);
  w.f32(layout.utilisation);
  w.u32(static_cast<uint32_t>(layout.instances.size()));
  for (const InstanceLightmapUv& region : layout.instances) {
    w.u32(region.instance);
    w.u32(static_cast<uint32_t>(region.cornerUv.size()));
    for (const glm::vec2& uv : region.cornerUv) w.f32(uv.x), w.f32(uv.y);
  }
  return w.take();
}

LightmapLayout decodeLayout(const fs::path& file, std::vector<unsigned char> bytes) {
  ByteReader r(file, bytes);
  if (!r.matches(kLayoutMagic, sizeof kLayoutMagic))
    throw LoadError(file, "bad magic: not a bounce lightmap layout");
  const uint32_t version = r.u32("the version");
  if (version != static_cast<uint32_t>(kBakeFormatVersion))
    throw LoadError(file, "format version " + std::to_string(version) +
                              ", this build reads version " + std::to_string(kBakeFormatVersion) +
                              ": rebake");
  LightmapLayout layout;
  layout.width = r.i32("the width");
  layout.height = r.i32("the height");
  layout.texelSize = r.f32("the texel size");
  layout.padding = r.i32("the padding");
  layout.chartCount = r.i32("the chart count");
  layout.utilisation = r.f32("the utilisation");
  const uint32_t count = r.u32("the instance count");
  // Each region takes at least 8 bytes: a count beyond that is a corrupt file, not a huge one.
  if (count > r.remaining() / 8)
    throw LoadError(file, "truncated: " + std::to_string(count) + " instance regions announced, " +
                              std::to_string(r.remaining()) + " bytes left");
  layout.instances.resize(count);
  for (InstanceLightmapUv& region : layout.instances) {
    region.instance = r.u32("an instance index");
    const uint32_t corners = r.u32("a corner count");
    r.need(static_cast<std::size_t>(corners) * 8, "the corner UVs");
    region.cornerUv.resize(corners);
    for (glm::vec2& uv : region.cornerUv) uv = {r.f32("u"), r.f32("v")};
  }
  if (r.remaining() != 0)
    throw LoadError(file, std::to_string(r.remaining()) + " bytes after the last instance region");
  return layout;
}

// The layout must describe this scene: one region per static instance with triangles at most,
// sorted, each with 3 corners per triangle, UVs in [0, 1].
void checkLayoutAgainstScene(const fs::path& file, const LightmapLayout& layout,
                             const Scene& scene) {
  if (layout.width <= 0 || layout.height <= 0 || layout.width > 65536 || layout.height > 65536)
    throw LoadError(file, "atlas size " + std::to_string(layout.width) + "x" +
                              std::to_string(layout.height) + " out of range 1..65536");
  if (!(std::isfinite(layout.texelSize) && layout.texelSize > 0.0f))
    throw LoadError(file, "texel size " + std::to_string(layout.texelSize) + " m is not positive");
  for (std::size_t i = 0; i < layout.instances.size(); ++i) {
    const InstanceLightmapUv& region = layout.instances[i];
    const std::string which =
        "region " + std::to_string(i) + ": instance " + std::to_string(region.instance);
    if (region.instance >= scene.instances.size())
      throw LoadError(file, which + " out of range (the scene has " +
                                std::to_string(scene.instances.size()) + " instances)");
    if (i > 0 && region.instance <= layout.instances[i - 1].instance)
      throw LoadError(file, which + " not in increasing order");
    const Instance& instance = scene.instances[region.instance];
    if (instance.mobility != Mobility::Static)
      throw LoadError(file, which + " ('" + instance.name + "') is dynamic and has no lightmap");
    const std::size_t triangles = scene.meshes.at(instance.mesh).triangleCount();
    if (region.cornerUv.size() != 3 * triangles)
      throw LoadError(file, which + " has " + std::to_string(region.cornerUv.size()) +
                                " corner UVs, its mesh needs 3 × " + std::to_string(triangles));
    // Atlas UVs lie in [0, 1]² (lightmap_layout.h); NaN fails both comparisons.
    for (const glm::vec2& uv : region.cornerUv)
      if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f))
        throw LoadError(file, which + " has a corner UV (" + std::to_string(uv.x) + ", " +
                                  std::to_string(uv.y) + ") outside [0, 1]");
  }
}

// Why a bake whose scene hash differs from the scene's does not match it, as far as bake.json
// and the files' times tell.
std::string whyStale(const fs::path& manifestFile, const BakeManifest& m, const Scene& scene,
                     const SceneHash& now) {
  const std::string sceneName = fs::path(scene.source).filename().string();
  if (!m.scene.empty() && !sceneName.empty() && m.scene != sceneName)
    return "it was made for another scene, " + m.scene;
  std::error_code sceneError, bakeError;
  const auto sceneTime = fs::last_write_time(scene.source, sceneError);
  const auto bakeTime = fs::last_write_time(manifestFile, bakeError);
  const bool editedSince =
      !scene.source.empty() && !sceneError && !bakeError && sceneTime > bakeTime;
  const std::string edited = editedSince ? "; " + scene.source + " was modified after it" : "";
  std::vector<std::string> changed;
  bool recorded = true;
  for (std::size_t i = 0; i < kScenePartNames.size(); ++i) {
    const auto part = m.sceneParts.find(kScenePartNames[i]);
    if (part == m.sceneParts.end())
      recorded = false;
    else if (part->second != now.parts[i])
      changed.push_back(kScenePartNames[i]);
  }
  if (!changed.empty()) {
    std::string list = changed[0];
    for (std::size_t i = 1; i < changed.size(); ++i)
      list += (i + 1 == changed.size() ? " and " : ", ") + changed[i];
    return "the scene changed since the bake: its " + list + " differ" + edited;
  }
  // What the hashes say comes first: file times are not kept by a checkout or a copy.
  if (recorded)
    return "every part's hash matches but the whole does not: made by a build of bounce that "
           "hashes scenes differently" +
           edited;
  if (editedSince) return "the scene changed since the bake" + edited;
  return "made for another scene or the scene changed since the bake (bake.json records no "
         "per-part hashes to tell which)";
}

// Removes "<dir>.tmp-<pid>" and "<dir>.old-<pid>" folders whose process is gone: what a bake
// killed while it wrote (kill -9, a power cut) leaves beside the folder.
void removeLeftovers(const fs::path& dir) {
  std::error_code ec;
  const fs::path parent = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  const std::string name = dir.filename().string();
  for (const fs::directory_entry& entry : fs::directory_iterator(parent, ec)) {
    const std::string other = entry.path().filename().string();
    for (const std::string mark : {".tmp-", ".old-"}) {
      const std::string prefix = name + mark;
      if (!other.starts_with(prefix) || other.size() == prefix.size()) continue;
      const std::string pid = other.substr(prefix.size());
      if (pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) continue;
      const pid_t owner = static_cast<pid_t>(std::stol(pid));
      if (owner != ::getpid() && ::kill(owner, 0) != 0 && errno == ESRCH)
        fs::remove_all(entry.path(), ec);
    }
  }
}

// Swaps `fresh` into `dir`. With an existing `dir`, renameat2(RENAME_EXCHANGE) swaps the two
// names atomically, so `dir` always names a whole bake; `fresh` then holds the old one, which is
// removed. File systems without the exchange fall back to two renames (dir → .old, fresh → dir).
void replaceFolder(const fs::path& fresh, const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir)) {
    fs::rename(fresh, dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot rename into place: " + ec.message());
    return;
  }
  if (::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(fresh, ec);  // the previous bake; a leftover only wastes space
    return;
  }
  if (errno != EINVAL && errno != ENOSYS)
    throw std::runtime_error(dir.string() +
                             ": cannot swap the new bake in: " + std::strerror(errno));
  fs::path old = dir;
  old += ".old-" + std::to_string(::getpid());
  fs::remove_all(old, ec);
  fs::rename(dir, old, ec);
  if (ec)
    throw std::runtime_error(dir.string() + ": cannot move the old bake aside: " + ec.message());
  fs::rename(fresh, dir, ec);
  if (ec) {
    std::error_code ignored;
    fs::rename(old, dir, ignored);
    throw std::runtime_error(dir.string() + ": cannot rename into place: " + ec.message());
  }
  fs::remove_all(old, ec);
}

// An EXR of the bake folder, one texel per atlas texel: its size must be the layout's.
Image readLayoutExr(const fs::path& file, const LightmapLayout& layout) {
  Image image;
  try {
    image = readExr(file);
  } catch (const std::runtime_error& e) {
    std::string why = e.what();
    const std::string prefix = file.string() + ": ";
    if (why.starts_with(prefix)) why.erase(0, prefix.size());
    throw LoadError(file, why);
  }
  if (image.width != layout.width || image.height != layout.height)
    throw LoadError(file, "is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                              ", " + kLayoutName + " says " + std::to_string(layout.width) + "x" +
                              std::to_string(layout.height));
  return image;
}

// The files a bake folder may hold besides bake.json; bake.json records each one present.
constexpr const char* kFolderFiles[] = {kLayoutName,  kLightmapName,       kErrorMapName,
                                        kVplFileName, kVisibilityFileName, kProbeFileName};

// What the manifest says must agree with the folder's files: the first disagreement as (file,
// reason), or nullopt. Shared by the writer (a caller's bug) and the reader (a damaged folder).
// The layout's part, checked as soon as layout.bin is read: the other files are sized by it.
std::optional<std::string> layoutDisagreement(const BakeManifest& m, const LightmapLayout& layout) {
  const auto size = [](auto w, auto h) { return std::to_string(w) + "x" + std::to_string(h); };
  if (m.atlas.width != layout.width || m.atlas.height != layout.height)
    return "is " + size(layout.width, layout.height) + ", bake.json's atlas is " +
           size(m.atlas.width, m.atlas.height) + ": another bake's";
  if (m.atlas.regions != layout.instances.size())
    return "has " + std::to_string(layout.instances.size()) +
           " instance regions, bake.json's atlas has " + std::to_string(m.atlas.regions);
  return std::nullopt;
}

std::optional<std::pair<std::string, std::string>> disagreement(const BakeManifest& m,
                                                                const Bake& bake) {
  if (const auto why = layoutDisagreement(m, bake.layout)) return std::pair{kLayoutName, *why};
  if (m.vpls.has_value() != bake.vpls.has_value())
    return std::pair{kVplFileName, bake.vpls ? "present, but bake.json describes no VPLs"
                                             : "missing, bake.json describes VPLs"};
  if (bake.vpls && m.vpls->count != bake.vpls->size())
    return std::pair{kVplFileName, "holds " + std::to_string(bake.vpls->size()) +
                                       " VPLs, bake.json says " + std::to_string(m.vpls->count)};
  if (m.visibility.has_value() != bake.visibility.has_value())
    return std::pair{kVisibilityFileName, bake.visibility
                                              ? "present, but bake.json describes no visibility"
                                              : "missing, bake.json describes a visibility"};
  if (bake.visibility && m.visibility->lights != bake.visibility->lightCount)
    return std::pair{kVisibilityFileName, "holds " + std::to_string(bake.visibility->lightCount) +
                                              " lights, bake.json says " +
                                              std::to_string(m.visibility->lights)};
  if (bake.visibility && m.visibility->punctualLights != bake.visibility->punctualCount)
    return std::pair{kVisibilityFileName, "holds " +
                                              std::to_string(bake.visibility->punctualCount) +
                                              " punctual lights, bake.json says " +
                                              std::to_string(m.visibility->punctualLights)};
  if (m.probes.has_value() != bake.probes.has_value())
    return std::pair{kProbeFileName, bake.probes ? "present, but bake.json describes no probes"
                                                 : "missing, bake.json describes probes"};
  if (bake.probes && (m.probes->count != bake.probes->probes.size() ||
                      m.probes->grids != bake.probes->grids.size()))
    return std::pair{kProbeFileName, "holds " + std::to_string(bake.probes->probes.size()) +
                                         " probes in " + std::to_string(bake.probes->grids.size()) +
                                         " grids, bake.json says " +
                                         std::to_string(m.probes->count) + " in " +
                                         std::to_string(m.probes->grids)};
  return std::nullopt;
}

// Every probe grid lies around a static instance of `scene` that has no lightmap region.
void checkProbesAgainstScene(const fs::path& file, const IrradianceProbes& probes,
                             const LightmapLayout& layout, const Scene& scene) {
  for (std::size_t i = 0; i < probes.grids.size(); ++i) {
    const uint32_t instance = probes.grids[i].instance;
    const std::string which =
        "grid " + std::to_string(i) + ": instance " + std::to_string(instance);
    if (instance >= scene.instances.size())
      throw LoadError(file, which + " out of range (the scene has " +
                                std::to_string(scene.instances.size()) + " instances)");
    if (scene.instances[instance].mobility != Mobility::Static)
      throw LoadError(file, which + " ('" + scene.instances[instance].name +
                                "') is dynamic: its light comes from the VPLs");
    if (layout.find(instance) != nullptr)
      throw LoadError(file,
                      which + " ('" + scene.instances[instance].name + "') has a lightmap region");
    const std::size_t corners = 3 * scene.meshes.at(scene.instances[instance].mesh).triangleCount();
    if (probes.grids[i].cornerCount != 0 && probes.grids[i].cornerCount != corners)
      throw LoadError(file, which + " ('" + scene.instances[instance].name + "') has " +
                                std::to_string(probes.grids[i].cornerCount) +
                                " visibility corners, its mesh " + std::to_string(corners) +
                                ": rebake");
  }
  if (probes.visibility.corners.empty()) return;
  const std::size_t lights = sceneAreaLights(scene).staticCount();
  if (probes.visibility.lightCount != lights ||
      probes.visibility.punctualCount != scene.lights.size())
    throw LoadError(
        file, "its corners name " + std::to_string(probes.visibility.lightCount) +
                  " static area and " + std::to_string(probes.visibility.punctualCount) +
                  " punctual lights, " + scene.source + " has " + std::to_string(lights) + " and " +
                  std::to_string(scene.lights.size()) + ": rebake");
}

// Every file bake.json records is there with its recorded size and hash, and every file of the
// folder is recorded: a damaged, truncated, swapped or foreign file is refused before it is
// parsed. Returns the files' bytes by name.
std::map<std::string, std::vector<unsigned char>> readRecordedFiles(const fs::path& dir,
                                                                    const BakeManifest& m) {
  const fs::path manifestFile = dir / kManifestName;
  for (const auto& record : m.files)
    if (std::find_if(std::begin(kFolderFiles), std::end(kFolderFiles), [&](const char* known) {
          return record.first == known;
        }) == std::end(kFolderFiles))
      throw LoadError(manifestFile,
                      "\"files\" records \"" + record.first + "\", not a bake folder file");
  for (const char* required : {kLayoutName, kLightmapName})
    if (!m.files.contains(required))
      throw LoadError(manifestFile, std::string("\"files\" does not record ") + required);
  std::map<std::string, std::vector<unsigned char>> bytes;
  for (const char* name : kFolderFiles) {
    const fs::path file = dir / name;
    const auto record = m.files.find(name);
    if (record == m.files.end()) {
      if (fs::exists(file))
        throw LoadError(file, "not recorded in bake.json's \"files\": another bake's: rebake");
      continue;
    }
    std::vector<unsigned char> content = readBakeInputFile(file);
    if (content.size() != record->second.bytes)
      throw LoadError(file, std::to_string(content.size()) + " bytes, bake.json records " +
                                std::to_string(record->second.bytes) + ": damaged: rebake");
    const std::string hash = fnv1a64Hex(content);
    if (hash != record->second.hash)
      throw LoadError(file, "its hash is " + hash + ", bake.json records " + record->second.hash +
                                ": damaged or another bake's: rebake");
    bytes[name] = std::move(content);
  }
  return bytes;
}

// Irradiance the renderer can draw: finite, non-negative, below kMaxBakeIrradiance.
void checkIrradiance(const fs::path& file, const Image& irradiance) {
  for (std::size_t i = 0; i < irradiance.pixels.size(); ++i) {
    const glm::vec3 e = irradiance.pixels[i];
    for (int c = 0; c < 3; ++c)
      if (!(e[c] >= 0.0f && e[c] <= kMaxBakeIrradiance))
        throw LoadError(file, "texel (" + std::to_string(i % irradiance.width) + ", " +
                                  std::to_string(i / irradiance.width) + ") holds irradiance " +
                                  std::to_string(e[c]) + " W/m^2, outside [0, " +
                                  shortNumber(kMaxBakeIrradiance) + "]");
  }
}

}  // namespace

Bake readBake(const fs::path& dir, const Scene& scene) {
  if (!fs::is_directory(dir))
    throw LoadError(dir,
                    fs::exists(dir) ? "not a folder" : "no bake folder here (run bounce-bake)");

  Bake bake;
  const fs::path manifestFile = dir / kManifestName;
  const std::vector<unsigned char> manifestBytes =
      readBakeInputFile(manifestFile, kMaxBakeManifestBytes);
  bake.manifest =
      parseManifest(manifestFile, std::string(manifestBytes.begin(), manifestBytes.end()));
  const BakeManifest& manifest = bake.manifest;
  const SceneHash hash = sceneHash(scene);
  if (manifest.sceneHash != hash.whole)
    throw StaleBakeError(manifestFile, "stale bake: it does not match the scene (" +
                                           whyStale(manifestFile, manifest, scene, hash) +
                                           "): its scene hash is " + manifest.sceneHash + ", " +
                                           scene.source + " hashes to " + hash.whole + ": rebake");
  std::map<std::string, std::vector<unsigned char>> files = readRecordedFiles(dir, manifest);

  const fs::path layoutFile = dir / kLayoutName;
  bake.layout = decodeLayout(layoutFile, std::move(files[kLayoutName]));
  checkLayoutAgainstScene(layoutFile, bake.layout, scene);
  if (const auto why = layoutDisagreement(manifest, bake.layout)) throw LoadError(layoutFile, *why);

  const fs::path lightmapFile = dir / kLightmapName;
  bake.irradiance = readLayoutExr(lightmapFile, bake.layout);
  checkIrradiance(lightmapFile, bake.irradiance);
  const fs::path errorFile = dir / kErrorMapName;
  if (files.contains(kErrorMapName)) {
    bake.relativeError = readLayoutExr(errorFile, bake.layout);
    for (const glm::vec3& e : bake.relativeError->pixels)
      if (!(e.r == kNoErrorEstimate || (e.r >= 0.0f && e.r <= kMaxRelativeError)) || e.g != e.r ||
          e.b != e.r)
        throw LoadError(errorFile, "holds a texel of (" + std::to_string(e.r) + ", " +
                                       std::to_string(e.g) + ", " + std::to_string(e.b) +
                                       "): each texel is one relative error in [0, " +
                                       std::to_string(kMaxRelativeError) +
                                       "] in all three channels, or -1 for none");
  }
  if (files.contains(kVplFileName)) bake.vpls = decodeVpls(dir / kVplFileName, files[kVplFileName]);
  const fs::path visibilityFile = dir / kVisibilityFileName;
  if (files.contains(kVisibilityFileName)) {
    bake.visibility = decodeVisibility(visibilityFile, files[kVisibilityFileName]);
    if (bake.visibility->width != bake.layout.width ||
        bake.visibility->height != bake.layout.height)
      throw LoadError(visibilityFile, "is " + std::to_string(bake.visibility->width) + "x" +
                                          std::to_string(bake.visibility->height) + ", " +
                                          kLayoutName + " says " +
                                          std::to_string(bake.layout.width) + "x" +
                                          std::to_string(bake.layout.height));
    const std::size_t lights = sceneAreaLights(scene).staticCount();
    if (bake.visibility->lightCount != lights)
      throw LoadError(visibilityFile, "holds " + std::to_string(bake.visibility->lightCount) +
                                          " static area lights, " + scene.source + " has " +
                                          std::to_string(lights) + ": rebake");
    if (bake.visibility->punctualCount != scene.lights.size())
      throw LoadError(visibilityFile, "holds " + std::to_string(bake.visibility->punctualCount) +
                                          " punctual lights, " + scene.source + " has " +
                                          std::to_string(scene.lights.size()) + ": rebake");
  }
  if (files.contains(kProbeFileName)) {
    const fs::path probeFile = dir / kProbeFileName;
    bake.probes = decodeProbes(probeFile, files[kProbeFileName]);
    checkProbesAgainstScene(probeFile, *bake.probes, bake.layout, scene);
  }
  if (const auto why = disagreement(manifest, bake)) throw LoadError(dir / why->first, why->second);
  checkManifestRules(manifestFile, bake, scene);
  return bake;
}

void writeBake(const fs::path& dir, const Bake& bake) {
  const auto fail = [&](const std::string& why) {
    throw std::runtime_error(dir.string() + ": " + why);
  };
  if (bake.manifest.formatVersion != kBakeFormatVersion)
    fail("manifest formatVersion " + std::to_string(bake.manifest.formatVersion) + " is not " +
         std::to_string(kBakeFormatVersion));
  if (bake.manifest.sceneHash.empty()) fail("manifest has no sceneHash");
  if (bake.layout.width <= 0 || bake.layout.height <= 0 ||
      bake.irradiance.width != bake.layout.width || bake.irradiance.height != bake.layout.height ||
      bake.irradiance.pixels.size() != static_cast<std::size_t>(bake.irradiance.width) *
                                           static_cast<std::size_t>(bake.irradiance.height))
    fail("lightmap " + std::to_string(bake.irradiance.width) + "x" +
         std::to_string(bake.irradiance.height) + " does not match the layout's " +
         std::to_string(bake.layout.width) + "x" + std::to_string(bake.layout.height));
  if (bake.relativeError && (bake.relativeError->width != bake.layout.width ||
                             bake.relativeError->height != bake.layout.height))
    fail("error map " + std::to_string(bake.relativeError->width) + "x" +
         std::to_string(bake.relativeError->height) + " does not match the layout");
  if (const auto why = disagreement(bake.manifest, bake))
    fail("manifest disagrees with " + why->first + ": " + why->second);

  fs::path tmp = dir;
  tmp += ".tmp-" + std::to_string(::getpid());
  std::error_code ec;
  removeLeftovers(dir);
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp, ec);
  if (ec) fail("cannot create " + tmp.string() + ": " + ec.message());
  try {
    // bake.json last: its time stamp is the folder's (the build step's output, BounceBake.cmake).
    writeFileAtomically(tmp / kLayoutName, encodeLayout(bake.layout));
    writeExr(tmp / kLightmapName, bake.irradiance);
    if (bake.vpls) writeVplFile(tmp / kVplFileName, *bake.vpls);
    if (bake.visibility) writeVisibilityFile(tmp / kVisibilityFileName, *bake.visibility);
    if (bake.relativeError) writeExr(tmp / kErrorMapName, *bake.relativeError);
    if (bake.probes) writeProbeFile(tmp / kProbeFileName, *bake.probes);
    // The records are of the bytes on disk, read back, as readBake will see them.
    BakeManifest manifest = bake.manifest;
    manifest.files.clear();
    for (const char* name : kFolderFiles)
      if (fs::exists(tmp / name)) {
        const std::vector<unsigned char> bytes = readBakeInputFile(tmp / name);
        manifest.files[name] = {bytes.size(), fnv1a64Hex(bytes)};
      }
    const std::string json = manifestText(manifest);
    writeFileAtomically(tmp / kManifestName,
                        {reinterpret_cast<const unsigned char*>(json.data()), json.size()});
    replaceFolder(tmp, dir);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace bounce
