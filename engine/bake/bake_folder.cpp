#include "bake/bake_folder.h"

#include <fcntl.h>  // AT_FDCWD
#include <stdio.h>  // renameat2, RENAME_EXCHANGE (glibc ≥ 2.28)
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/bake_input_file.h"
#include "bake/visibility_file.h"
#include "bake/vpl_file.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "scene/area_lights.h"
#include "scene/gltf_schema.h"  // checkJsonDepth
#include "scene/load_error.h"

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

// ---- little-endian byte stream for layout.bin
class ByteWriter {
 public:
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<unsigned char>(v >> (8 * i)));
  }
  void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
  void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
  void raw(const char* data, std::size_t n) { bytes_.insert(bytes_.end(), data, data + n); }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

class ByteReader {
 public:
  ByteReader(const fs::path& file, std::vector<unsigned char> bytes)
      : file_(file), bytes_(std::move(bytes)) {}
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - pos_ < n)
      throw LoadError(file_, "truncated: " + std::to_string(bytes_.size()) + " bytes, " + what +
                                 " needs " + std::to_string(n) + " more at byte " +
                                 std::to_string(pos_));
  }
  uint32_t u32(const char* what) {
    need(4, what);
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(bytes_[pos_ + i]) << (8 * i);
    pos_ += 4;
    return v;
  }
  int32_t i32(const char* what) { return static_cast<int32_t>(u32(what)); }
  float f32(const char* what) { return std::bit_cast<float>(u32(what)); }
  bool matches(const char* data, std::size_t n) {
    need(n, "the magic");
    const bool same = std::memcmp(bytes_.data() + pos_, data, n) == 0;
    pos_ += n;
    return same;
  }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  fs::path file_;
  std::vector<unsigned char> bytes_;
  std::size_t pos_ = 0;
};

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
  return w.bytes();
}

LightmapLayout decodeLayout(const fs::path& file, std::vector<unsigned char> bytes) {
  ByteReader r(file, std::move(bytes));
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
// sorted, each with 3 corners per triangle, UVs finite.
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
    for (const glm::vec2& uv : region.cornerUv)
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
        throw LoadError(file, which + " has a non-finite corner UV");
  }
}

struct Manifest {
  int formatVersion = 0;
  std::string sceneHash;
  // Optional, read only to explain a stale bake: the scene file's name ("scene") and the
  // per-part hashes ("sceneParts", scene_hash.h), empty when absent or malformed.
  std::string sceneFile;
  std::map<std::string, std::string> sceneParts;
};

// Parses and checks the two fields every reader and writer relies on; `fail` builds the error.
template <class Fail>
Manifest parseManifest(const std::string& text, Fail fail) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    fail(std::string("not JSON: ") + e.what());
  }
  if (!json.is_object()) fail("not a JSON object");
  Manifest m;
  const auto version = json.find("formatVersion");
  if (version == json.end() || !version->is_number_integer()) fail("no integer \"formatVersion\"");
  m.formatVersion = version->get<int>();
  const auto hash = json.find("sceneHash");
  if (hash == json.end() || !hash->is_string()) fail("no string \"sceneHash\"");
  m.sceneHash = hash->get<std::string>();
  const auto file = json.find("scene");
  if (file != json.end() && file->is_string()) m.sceneFile = file->get<std::string>();
  const auto parts = json.find("sceneParts");
  if (parts != json.end() && parts->is_object())
    for (auto part = parts->begin(); part != parts->end(); ++part)
      if (part->is_string()) m.sceneParts[part.key()] = part->get<std::string>();
  return m;
}

// Why a bake whose scene hash differs from the scene's does not match it, as far as bake.json
// and the files' times tell.
std::string whyStale(const fs::path& manifestFile, const Manifest& m, const Scene& scene,
                     const SceneHash& now) {
  const std::string sceneName = fs::path(scene.source).filename().string();
  if (!m.sceneFile.empty() && !sceneName.empty() && m.sceneFile != sceneName)
    return "it was made for another scene, " + m.sceneFile;
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

}  // namespace

Bake readBake(const fs::path& dir, const Scene& scene) {
  if (!fs::is_directory(dir))
    throw LoadError(dir,
                    fs::exists(dir) ? "not a folder" : "no bake folder here (run bounce-bake)");

  Bake bake;
  const fs::path manifestFile = dir / kManifestName;
  const std::vector<unsigned char> manifestBytes =
      readBakeInputFile(manifestFile, kMaxBakeManifestBytes);
  bake.manifestJson.assign(manifestBytes.begin(), manifestBytes.end());
  checkJsonDepth(manifestFile, bake.manifestJson);  // before the recursive parser
  const Manifest manifest = parseManifest(
      bake.manifestJson, [&](const std::string& why) { throw LoadError(manifestFile, why); });
  if (manifest.formatVersion != kBakeFormatVersion)
    throw LoadError(manifestFile, "format version " + std::to_string(manifest.formatVersion) +
                                      ", this build reads version " +
                                      std::to_string(kBakeFormatVersion) + ": rebake");
  const SceneHash hash = sceneHash(scene);
  if (manifest.sceneHash != hash.whole)
    throw LoadError(manifestFile, "stale bake: it does not match the scene (" +
                                      whyStale(manifestFile, manifest, scene, hash) +
                                      "): its scene hash is " + manifest.sceneHash + ", " +
                                      scene.source + " hashes to " + hash.whole + ": rebake");

  const fs::path layoutFile = dir / kLayoutName;
  bake.layout = decodeLayout(layoutFile, readBakeInputFile(layoutFile));
  checkLayoutAgainstScene(layoutFile, bake.layout, scene);

  const fs::path lightmapFile = dir / kLightmapName;
  if (!fs::exists(lightmapFile)) throw LoadError(lightmapFile, "missing");
  bake.irradiance = readLayoutExr(lightmapFile, bake.layout);
  const fs::path errorFile = dir / kErrorMapName;
  if (fs::exists(errorFile)) {
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
  if (fs::exists(dir / kVplFileName)) bake.vpls = readVplFile(dir / kVplFileName);
  const fs::path visibilityFile = dir / kVisibilityFileName;
  if (fs::exists(visibilityFile)) {
    bake.visibility = readVisibilityFile(visibilityFile);
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
  }
  return bake;
}

void writeBake(const fs::path& dir, const Bake& bake) {
  const auto fail = [&](const std::string& why) {
    throw std::runtime_error(dir.string() + ": " + why);
  };
  const Manifest manifest =
      parseManifest(bake.manifestJson, [&](const std::string& why) { fail("manifest " + why); });
  if (manifest.formatVersion != kBakeFormatVersion)
    fail("manifest formatVersion " + std::to_string(manifest.formatVersion) + " is not " +
         std::to_string(kBakeFormatVersion));
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

  fs::path tmp = dir;
  tmp += ".tmp-" + std::to_string(::getpid());
  std::error_code ec;
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
    const std::string& json = bake.manifestJson;
    writeFileAtomically(tmp / kManifestName,
                        {reinterpret_cast<const unsigned char*>(json.data()), json.size()});
    replaceFolder(tmp, dir);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace bounce
