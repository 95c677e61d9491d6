// The bake folder's `probes.bin`: the irradiance probes of a bake
// (bake_folder/irradiance_probes.h), a versioned little-endian binary, with its reader and writer
// here. GL-free.
//
//   offset      size      field
//   0           char[8]   magic "BNCPRBS\0"
//   8           u32       version (= kProbeFormatVersion)
//   12          u32       grid count G
//   16          u32       probe count P
//   20          u32       corner count C (baked visibility, 3 per triangle of the grids' meshes)
//   24          u32       static area lights L the corners may name
//   28          u32       punctual lights Q the corners may name (after the area lights)
//   32          G × 56    per grid: instance u32 | first probe u32 | counts x y z u32 |
//                         origin x y z f32 (m) | spacing x y z f32 (m) | normal offset f32 (m) |
//                         first corner u32 | corner count u32
//   32+56G      P × 48    per probe, 12 × f32: E00 r g b | E1−1 r g b | E10 r g b | E11 r g b
//                         (W/m², the L1 SH coefficients of the irradiance E(n), convention in
//                         irradiance_probes.h)
//   …           C × 24    per corner, as a texel of visibility.bin: 4 × u16 light (0..L−1 area
//                         light, L..L+Q−1 punctual light, 0xfffe every other light, 0xffff
//                         none) | 4 × f32 V (visible fraction, in [0, 1])
//   32+56G+48P+24C  —     end of file (nothing may follow)
//
// The reader refuses (LoadError naming the file and the reason) a wrong magic or version, a size
// that disagrees with G, P and C, a grid whose instances are not strictly ascending, whose count
// on an axis is under 2 or over kMaxProbeGridCount, whose first probe is not the sum of the
// earlier grids' counts or whose probes run past P, an origin not finite or beyond
// ±kMaxBakeLength m, a spacing not in (0, kMaxBakeLength] m, a normal offset not in
// [0, kMaxBakeLength] m, grids that leave probes unused, a coefficient not finite or beyond
// ±kMaxBakeIrradiance W/m², a mean irradiance Y00·E00 under 0; a grid whose first corner is not
// the sum of the earlier grids' corner counts, whose corner count is not a multiple of 3 or runs
// past C, grids that leave corners unused, L + Q over 0xfffd, and a corner naming a light ≥ L + Q
// that is not one of the two marks, a light twice, or a V not finite or outside [0, 1]. Which
// instances may have grids, and that a grid's corners are its mesh's, are the bake folder's
// checks (bake_folder.h: static, with no lightmap region, 3 corners per triangle).
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "bake_folder/irradiance_probes.h"

namespace bounce {

inline constexpr uint32_t kProbeFormatVersion = 2;  // 2: baked visibility per corner
inline constexpr char kProbeFileName[] = "probes.bin";
inline constexpr uint32_t kMaxProbeGridCount = 64;  // probes per axis of one grid

std::vector<unsigned char> encodeProbes(const IrradianceProbes& probes);
// `file` is only named in errors.
IrradianceProbes decodeProbes(const std::filesystem::path& file,
                              std::span<const unsigned char> bytes);

// Whole file or nothing (engine/image/atomic_file.h); throws std::runtime_error naming the file.
void writeProbeFile(const std::filesystem::path& file, const IrradianceProbes& probes);

}  // namespace bounce
