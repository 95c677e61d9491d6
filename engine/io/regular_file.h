// Reading a whole input file, regular files only. A FIFO, a device, a socket or a directory
// given where bounce expects a file is refused before it is opened (opening a FIFO for reading
// blocks until a writer appears; a device can stream forever), and so is a file larger than
// `maxBytes`. Every failure throws std::runtime_error "<file>: <reason>".
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace bounce {

// The largest input file bounce reads: 2 GiB (tinygltf and tinyexr index buffers with 32-bit
// sizes; docs/input_limits.md).
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{1} << 31;

// Empty when `path` names a regular file (symbolic links followed), else the reason:
// "file not found", "is a directory", "is a FIFO (named pipe)", "is a device", ….
std::string notRegularFileReason(const std::filesystem::path& path);

std::vector<unsigned char> readRegularFile(const std::filesystem::path& path,
                                           std::size_t maxBytes = kMaxInputFileBytes);

}  // namespace bounce
