#include "bake_folder/visibility_file.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "bake_folder/bake_input_file.h"
#include "io/atomic_file.h"
#include "io/byte_stream.h"
#include "io/load_error.h"

namespace bounce {
namespace {

constexpr char kVisibilityMagic[8] = {'B', 'N', 'C', 'V', 'I', 'S', 'I', 'B'};
constexpr std::size_t kVisibilityHeaderBytes = 28;
constexpr std::size_t kTexelBytes = 2 * kVisibilitySlots + 4 * kVisibilitySlots;

}  // namespace

std::vector<unsigned char> encodeVisibility(const BakedVisibility& visibility) {
  std::vector<unsigned char> out(kVisibilityHeaderBytes + kTexelBytes * visibility.texels.size(),
                                 0);
  for (std::size_t i = 0; i < sizeof kVisibilityMagic; ++i)
    out[i] = static_cast<unsigned char>(kVisibilityMagic[i]);
  storeU32(out, 8, kVisibilityFormatVersion);
  storeU32(out, 12, static_cast<uint32_t>(visibility.width));
  storeU32(out, 16, static_cast<uint32_t>(visibility.height));
  storeU32(out, 20, visibility.lightCount);
  storeU32(out, 24, visibility.punctualCount);
  for (std::size_t t = 0; t < visibility.texels.size(); ++t) {
    const std::size_t at = kVisibilityHeaderBytes + kTexelBytes * t;
    for (int s = 0; s < kVisibilitySlots; ++s) {
      storeU16(out, at + 2 * s, visibility.texels[t].light[s]);
      storeU32(out, at + 2 * kVisibilitySlots + 4 * s,
               std::bit_cast<uint32_t>(visibility.texels[t].visible[s]));
    }
  }
  return out;
}

BakedVisibility decodeVisibility(const std::filesystem::path& file,
                                 std::span<const unsigned char> bytes) {
  if (bytes.size() < kVisibilityHeaderBytes)
    throw LoadError(file, "truncated: " + std::to_string(bytes.size()) +
                              " bytes, the header needs " + std::to_string(kVisibilityHeaderBytes));
  if (std::memcmp(bytes.data(), kVisibilityMagic, sizeof kVisibilityMagic) != 0)
    throw LoadError(file, "bad magic: not a bounce visibility file");
  const uint32_t version = loadU32(bytes, 8);
  if (version != kVisibilityFormatVersion)
    throw LoadError(file, "format version " + std::to_string(version) +
                              ", this build reads version " +
                              std::to_string(kVisibilityFormatVersion) + ": rebake");
  const int32_t width = std::bit_cast<int32_t>(loadU32(bytes, 12));
  const int32_t height = std::bit_cast<int32_t>(loadU32(bytes, 16));
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
    throw LoadError(file, "size " + std::to_string(width) + "x" + std::to_string(height) +
                              " is not between 1 and 65536 texels a side");
  BakedVisibility v;
  v.width = width;
  v.height = height;
  v.lightCount = loadU32(bytes, 20);
  v.punctualCount = loadU32(bytes, 24);
  if (uint64_t{v.lightCount} + v.punctualCount > kOtherLights - 1u)
    throw LoadError(file, std::to_string(v.lightCount) + " area and " +
                              std::to_string(v.punctualCount) +
                              " punctual lights: at most 65533 in all can be named");
  const uint64_t texels = static_cast<uint64_t>(width) * static_cast<uint64_t>(height);
  const uint64_t expected = kVisibilityHeaderBytes + kTexelBytes * texels;
  if (bytes.size() != expected)
    throw LoadError(file, std::to_string(width) + "x" + std::to_string(height) + " texels need " +
                              std::to_string(expected) + " bytes, the file has " +
                              std::to_string(bytes.size()));
  v.texels.resize(texels);
  for (std::size_t t = 0; t < texels; ++t) {
    const std::size_t at = kVisibilityHeaderBytes + kTexelBytes * t;
    TexelVisibility& texel = v.texels[t];
    const std::string which = "texel " + std::to_string(t) + ": ";
    for (int s = 0; s < kVisibilitySlots; ++s) {
      texel.light[s] = loadU16(bytes, at + 2 * s);
      texel.visible[s] = std::bit_cast<float>(loadU32(bytes, at + 2 * kVisibilitySlots + 4 * s));
      const uint16_t l = texel.light[s];
      if (l != kNoLight && l != kOtherLights && l >= v.indexCount())
        throw LoadError(
            file, which + "light " + std::to_string(l) + " of " + std::to_string(v.indexCount()));
      if (!(texel.visible[s] >= 0.0f && texel.visible[s] <= 1.0f))
        throw LoadError(file, which + "visible fraction is not in [0, 1]");
      for (int r = 0; r < s; ++r)
        if (l != kNoLight && texel.light[r] == l)
          throw LoadError(file, which + "names light " + std::to_string(l) + " twice");
    }
  }
  return v;
}

void writeVisibilityFile(const std::filesystem::path& file, const BakedVisibility& visibility) {
  writeFileAtomically(file, encodeVisibility(visibility));
}

BakedVisibility readVisibilityFile(const std::filesystem::path& file) {
  return decodeVisibility(file, readBakeInputFile(file));
}

}  // namespace bounce
