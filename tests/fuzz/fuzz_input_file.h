// The fuzz targets feed bounce's real loaders, which read files by name (an OBJ names its
// .mtl, a glTF its buffers): each input is written to a private folder and loaded from there.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace bounce::fuzz {

// Writes `data` to "<tmp>/bounce-fuzz-<pid>/<name>" and returns that path.
inline std::filesystem::path writeInput(const uint8_t* data, std::size_t size,
                                        const std::string& name) {
  static const std::filesystem::path folder = [] {
    std::filesystem::path f =
        std::filesystem::temp_directory_path() / ("bounce-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  const std::filesystem::path path = folder / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace bounce::fuzz
