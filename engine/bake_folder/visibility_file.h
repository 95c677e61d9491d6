// The bake folder's `visibility.bin` (bake_folder/light_visibility.h), little-endian, no padding:
//
//   offset  size        field
//   0       char[8]     magic "BNCVISIB"
//   8       u32         version (= kVisibilityFormatVersion)
//   12      i32         width  (texels, = the lightmap's)
//   16      i32         height
//   20      u32         lightCount L (static area lights, scene/area_lights.h order)
//   24      u32         punctualCount P (the scene's punctual lights, Scene::lights order)
//   28      W·H × 24    per texel, rows top first: 4 × u16 light (0..L−1 area light l,
//                       L..L+P−1 punctual light l − L, 0xfffe every other light, 0xffff none)
//                       | 4 × f32 V (visible fraction, in [0, 1])
//   —       —           end of file (nothing may follow)
//
// The reader refuses (LoadError naming the file and the reason) a wrong magic or version, a size
// that disagrees with the header, L + P over 0xfffd, a light index ≥ L + P that is not one of
// the two marks, a V that
// is not finite or outside [0, 1], and a light named twice in one texel.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "bake_folder/light_visibility.h"

namespace bounce {

inline constexpr uint32_t kVisibilityFormatVersion = 2;  // 2: punctual lights
inline constexpr char kVisibilityFileName[] = "visibility.bin";

std::vector<unsigned char> encodeVisibility(const BakedVisibility& visibility);
// `file` is only named in errors.
BakedVisibility decodeVisibility(const std::filesystem::path& file,
                                 std::span<const unsigned char> bytes);

// Whole file or nothing (engine/image/atomic_file.h); throws std::runtime_error naming the file.
void writeVisibilityFile(const std::filesystem::path& file, const BakedVisibility& visibility);
// Throws LoadError naming the file and the reason (missing, unreadable, malformed).
BakedVisibility readVisibilityFile(const std::filesystem::path& file);

}  // namespace bounce
