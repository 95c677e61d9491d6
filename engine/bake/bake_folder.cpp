#include "bake/bake_folder.h"

#include <fcntl.h>  // AT_FDCWD
#include <stdio.h>  // renameat2, RENAME_EXCHANGE (glibc ≥ 2.28)
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
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
constexpr char kLayoutName[] = "layout.bin";

// layout.bin, all values little-endian, no padding:
//   char[8] magic "BNCLMLAY" | u32 version (= kBakeFormatVersion)
//   i32 width | i32 height | f32 texelSize (m) | i32 padding | i32 chartCount | f32 utilisation
//   u32 instanceCount, then per instance: u32 instance | u32 cornerCount | cornerCount × (f32 u,
//   f32 v)
// and nothing after the last instance.
constexpr char kLayoutMagic[8] = {'B', 'N', 'C', 'L', 'M', 'L', 'A', 'Y'};

// ---- the scene hash: FNV-1a (64 bit) over a little-endian serialisation, each array length
// first so that moving a value from one array to the next changes the hash.
class ContentHash {
 public:
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      state_ ^= p[i];
      state_ *= 0x100000001b3ull;
    }
  }
  void u64(uint64_t v) {
    unsigned char b[8];
    for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(v >> (8 * i));
    bytes(b, 8);
  }
  // Bit pattern, with −0 as +0 and every NaN as one NaN: equal values hash equal.
  void f32(float v) {
    if (v == 0.0f) v = 0.0f;
    if (std::isnan(v)) v = std::numeric_limits<float>::quiet_NaN();
    u64(std::bit_cast<uint32_t>(v));
  }
  void vec(const glm::vec2& v) { f32(v.x), f32(v.y); }
  void vec(const glm::vec3& v) { f32(v.x), f32(v.y), f32(v.z); }
  template <class T>
  void array(const std::vector<T>& values) {
    u64(values.size());
    for (const T& v : values) vec(v);
  }
  std::string hex() const {
    static const char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 0; i < 16; ++i) s[15 - i] = digits[(state_ >> (4 * i)) & 0xf];
    return s;
  }

 private:
  uint64_t state_ = 0xcbf29ce484222325ull;
};

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
  return m;
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

}  // namespace

std::string sceneContentHash(const Scene& scene) {
  ContentHash h;
  // Names do not change light, so they are left out; everything that does is in.
  h.u64(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    h.array(mesh.positions);
    h.array(mesh.normals);
    h.array(mesh.uv0);
    h.array(mesh.uv1);
    h.u64(mesh.indices.size());
    for (uint32_t i : mesh.indices) h.u64(i);
    h.u64(mesh.material);
  }
  h.u64(scene.materials.size());
  for (const Material& m : scene.materials) {
    h.vec(m.albedo);
    h.u64(m.albedoTexture ? uint64_t{*m.albedoTexture} + 1 : 0);
    h.vec(m.emission);
    h.u64(m.doubleSided ? 1 : 0);
  }
  h.u64(scene.textures.size());
  for (const Texture& t : scene.textures) {
    h.u64(static_cast<uint64_t>(t.width));
    h.u64(static_cast<uint64_t>(t.height));
    h.array(t.texels);
  }
  h.u64(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    h.u64(instance.mesh);
    // A dynamic instance is in neither the lightmap nor the VPLs (the bake runs without it):
    // the bake holds wherever it is placed (--move, the viewer), so its transform is left out.
    if (instance.mobility == Mobility::Dynamic) {
      h.u64(static_cast<uint64_t>(instance.mobility));
      continue;
    }
    for (int c = 0; c < 4; ++c) {
      const glm::vec4 column = instance.transform[c];
      h.f32(column.x), h.f32(column.y), h.f32(column.z), h.f32(column.w);
    }
    h.u64(static_cast<uint64_t>(instance.mobility));
  }
  h.u64(scene.lights.size());
  for (const Light& light : scene.lights) {
    h.u64(static_cast<uint64_t>(light.type));
    h.vec(light.position);
    h.vec(light.direction);
    h.vec(light.intensity);
    h.vec(light.irradiance);
    h.f32(light.innerConeAngle);
    h.f32(light.outerConeAngle);
    h.u64(light.bakeDirect ? 1 : 0);  // whether its direct light is in the map
  }
  return h.hex();
}

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
  const std::string hash = sceneContentHash(scene);
  if (manifest.sceneHash != hash)
    throw LoadError(manifestFile, "bake made for another scene: rebake (bake's scene hash " +
                                      manifest.sceneHash + ", " + scene.source + " has " + hash +
                                      ")");

  const fs::path layoutFile = dir / kLayoutName;
  bake.layout = decodeLayout(layoutFile, readBakeInputFile(layoutFile));
  checkLayoutAgainstScene(layoutFile, bake.layout, scene);

  const fs::path lightmapFile = dir / kLightmapName;
  if (!fs::exists(lightmapFile)) throw LoadError(lightmapFile, "missing");
  try {
    bake.irradiance = readExr(lightmapFile);
  } catch (const std::runtime_error& e) {
    std::string why = e.what();
    const std::string prefix = lightmapFile.string() + ": ";
    if (why.starts_with(prefix)) why.erase(0, prefix.size());
    throw LoadError(lightmapFile, why);
  }
  if (bake.irradiance.width != bake.layout.width || bake.irradiance.height != bake.layout.height)
    throw LoadError(lightmapFile, "is " + std::to_string(bake.irradiance.width) + "x" +
                                      std::to_string(bake.irradiance.height) + ", " + kLayoutName +
                                      " says " + std::to_string(bake.layout.width) + "x" +
                                      std::to_string(bake.layout.height));
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
