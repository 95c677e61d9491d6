// Reading one file of a bake folder: regular files only, at most `maxBytes` (a FIFO named
// layout.bin would block the reader forever; image/regular_file.h), every failure a LoadError
// naming the file and the reason ("missing", "is a FIFO (named pipe)", "larger than …").
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "io/regular_file.h"

namespace bounce {

// bake.json is a small manifest; 16 MiB leaves room for any per-light or per-bounce lists.
inline constexpr std::size_t kMaxBakeManifestBytes = std::size_t{16} << 20;

std::vector<unsigned char> readBakeInputFile(const std::filesystem::path& file,
                                             std::size_t maxBytes = kMaxInputFileBytes);

}  // namespace bounce
