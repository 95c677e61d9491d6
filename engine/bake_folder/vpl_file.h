// The bake folder's `vpls` file: the virtual point lights of a bake (bake_folder/vpl.h), a
// versioned little-endian binary, with its reader and writer here. GL-free.
//
//   offset  size        field
//   0       char[8]     magic "BNCVPLS\0"
//   8       u32         version (= kVplFormatVersion)
//   12      u32         count N
//   16      N × 52      per VPL, 12 × f32 then u32: position x y z (m) | normal x y z (unit) |
//                       flux Φ r g b (W per channel, albedo of its surface included) |
//                       from x y z (m, where its incoming light-path segment started) |
//                       path index (u32; a path's VPLs are consecutive, in bounce order)
//   16+52N  —           end of file (nothing may follow)
//
// Version 2 added `from` and the path index (bake_folder/vpl.h); version 1 files are refused
// ("rebake"). The reader refuses (LoadError naming the file and the reason) a wrong magic or
// version, a size that disagrees with N, a position or `from` not finite or beyond ±kMaxBakeLength
// m in a coordinate, a normal not of unit length (±1e-3), a flux that is negative, not finite or
// over kMaxVplFlux W (bake_manifest.h), and a path index smaller than the previous VPL's.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "bake_folder/vpl.h"

namespace bounce {

inline constexpr uint32_t kVplFormatVersion = 2;
inline constexpr char kVplFileName[] = "vpls";

std::vector<unsigned char> encodeVpls(std::span<const Vpl> vpls);
// `file` is only named in errors.
std::vector<Vpl> decodeVpls(const std::filesystem::path& file,
                            std::span<const unsigned char> bytes);

// Whole file or nothing (engine/image/atomic_file.h); throws std::runtime_error naming the file.
void writeVplFile(const std::filesystem::path& file, std::span<const Vpl> vpls);
// Throws LoadError naming the file and the reason (missing, unreadable, malformed).
std::vector<Vpl> readVplFile(const std::filesystem::path& file);

}  // namespace bounce
