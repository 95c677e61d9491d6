// Small glTF files written by tests into a private temporary folder (never committed): a
// valid one-triangle document that each test corrupts or extends in one way.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace bounce::test {

// A fresh folder under the system temp dir, removed with its content on destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

struct GltfFixture {
  nlohmann::json doc;              // buffers[0] gets its uri/byteLength on write
  std::vector<unsigned char> bin;  // buffer 0

  // One triangle (0,0,0), (1,0,0), (0,1,0) facing +z, uint16 indices 0 1 2, one node.
  static GltfFixture triangle();
  // Appends float data as a new bufferView + accessor; returns the accessor index.
  int addFloats(const std::vector<float>& values, const std::string& type);

  void setFloat(std::size_t byteOffset, float value);
  // .gltf with the buffer in "<stem>.bin" next to it.
  void writeGltf(const std::filesystem::path& path) const;
  void writeGlb(const std::filesystem::path& path) const;
};

void writeText(const std::filesystem::path& path, const std::string& text);
std::vector<unsigned char> readAll(const std::filesystem::path& path);
void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

}  // namespace bounce::test
