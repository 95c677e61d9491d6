// The bake folder's `probes.bin`: the irradiance probes of a bake
// (bake_folder/irradiance_probes.h), a versioned little-endian binary, with its reader and writer
// here. GL-free.
//
//   offset      size      field
//   0           char[8]   magic "BNCPRBS\0"
//   8           u32       version (= kProbeFormatVersion)
//   12          u32       grid count G
//   16          u32       probe count P
//   20          G × 48    per grid: instance u32 | first probe u32 | counts x y z u32 |
//                         origin x y z f32 (m) | spacing x y z f32 (m) | normal offset f32 (m)
//   20+48G      P × 48    per probe, 12 × f32: E00 r g b | E1−1 r g b | E10 r g b | E11 r g b
//                         (W/m², the L1 SH coefficients of the irradiance E(n), convention in
//                         irradiance_probes.h)
//   20+48(G+P)  —         end of file (nothing may follow)
//
// The reader refuses (LoadError naming the file and the reason) a wrong magic or version, a size
// that disagrees with G and P, a grid whose instances are not strictly ascending, whose count on
// an axis is under 2 or over kMaxProbeGridCount, whose first probe is not the sum of the earlier
// grids' counts or whose probes run past P, an origin not finite or beyond ±kMaxBakeLength m, a
// spacing not in (0, kMaxBakeLength] m, a normal offset not in [0, kMaxBakeLength] m, grids that
// leave probes unused, a coefficient not finite or beyond ±kMaxBakeIrradiance W/m², and a mean
// irradiance Y00·E00 under 0. Which instances may have grids is the bake folder's check
// (bake_folder.h: static, with no lightmap region).
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "bake_folder/irradiance_probes.h"

namespace bounce {

inline constexpr uint32_t kProbeFormatVersion = 1;
inline constexpr char kProbeFileName[] = "probes.bin";
inline constexpr uint32_t kMaxProbeGridCount = 64;  // probes per axis of one grid

std::vector<unsigned char> encodeProbes(const IrradianceProbes& probes);
// `file` is only named in errors.
IrradianceProbes decodeProbes(const std::filesystem::path& file,
                              std::span<const unsigned char> bytes);

// Whole file or nothing (engine/image/atomic_file.h); throws std::runtime_error naming the file.
void writeProbeFile(const std::filesystem::path& file, const IrradianceProbes& probes);

}  // namespace bounce
