#include "gltf_fixture.h"

#include <unistd.h>

#include <atomic>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace bounce::test {

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("bounce_scene_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

GltfFixture GltfFixture::triangle() {
  GltfFixture f;
  f.doc = {{"asset", {{"version", "2.0"}}},
           {"scene", 0},
           {"scenes", {{{"nodes", {0}}}}},
           {"nodes", {{{"name", "tri"}, {"mesh", 0}}}},
           {"meshes",
            {{{"name", "tri"},
              {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", 4}}}}}}},
           {"accessors", nlohmann::json::array()},
           {"bufferViews", nlohmann::json::array()},
           {"buffers", nlohmann::json::array({nlohmann::json::object()})}};
  f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const std::size_t offset = f.bin.size();
  const uint16_t indices[4] = {0, 1, 2, 0};  // padded to 4-byte alignment
  f.bin.resize(offset + sizeof indices);
  std::memcpy(f.bin.data() + offset, indices, sizeof indices);
  f.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", 6}});
  f.doc["accessors"].push_back({{"bufferView", f.doc["bufferViews"].size() - 1},
                                {"componentType", 5123},
                                {"count", 3},
                                {"type", "SCALAR"}});
  return f;
}

int GltfFixture::addFloats(const std::vector<float>& values, const std::string& type) {
  const std::size_t offset = bin.size();
  bin.resize(offset + values.size() * sizeof(float));
  std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(float));
  doc["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(float)}});
  const std::size_t width = type == "VEC3" ? 3 : type == "VEC2" ? 2 : 1;
  doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                              {"componentType", 5126},
                              {"count", values.size() / width},
                              {"type", type}});
  return static_cast<int>(doc["accessors"].size() - 1);
}

void GltfFixture::setFloat(std::size_t byteOffset, float value) {
  std::memcpy(bin.data() + byteOffset, &value, sizeof value);
}

void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  writeBytes(path, std::vector<unsigned char>(text.begin(), text.end()));
}

std::vector<unsigned char> readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void GltfFixture::writeGltf(const std::filesystem::path& path) const {
  nlohmann::json d = doc;
  const std::string binName = path.stem().string() + ".bin";
  d["buffers"][0]["uri"] = binName;
  d["buffers"][0]["byteLength"] = bin.size();
  writeText(path, d.dump(1));
  writeBytes(path.parent_path() / binName, bin);
}

void GltfFixture::writeGlb(const std::filesystem::path& path) const {
  nlohmann::json d = doc;
  d["buffers"][0].erase("uri");
  d["buffers"][0]["byteLength"] = bin.size();
  std::string json = d.dump();
  while (json.size() % 4) json.push_back(' ');
  std::vector<unsigned char> b = bin;
  while (b.size() % 4) b.push_back(0);
  std::vector<unsigned char> out;
  auto u32 = [&](uint32_t v) {
    unsigned char bytes[4];
    std::memcpy(bytes, &v, 4);
    out.insert(out.end(), bytes, bytes + 4);
  };
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + b.size()));
  u32(static_cast<uint32_t>(json.size()));
  out.insert(out.end(), {'J', 'S', 'O', 'N'});
  out.insert(out.end(), json.begin(), json.end());
  u32(static_cast<uint32_t>(b.size()));
  out.insert(out.end(), {'B', 'I', 'N', '\0'});
  out.insert(out.end(), b.begin(), b.end());
  writeBytes(path, out);
}

}  // namespace bounce::test
