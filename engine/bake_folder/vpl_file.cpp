#include "bake_folder/vpl_file.h"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>

#include "bake_folder/bake_input_file.h"
#include "bake_folder/bake_manifest.h"  // the ranges
#include "io/atomic_file.h"
#include "io/byte_stream.h"
#include "io/load_error.h"

namespace bounce {
namespace {

constexpr char kVplMagic[8] = {'B', 'N', 'C', 'V', 'P', 'L', 'S', '\0'};
constexpr std::size_t kVplHeaderBytes = 16;
constexpr std::size_t kRecordBytes = 52;

bool finite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Each coordinate finite and within ±limit (NaN fails the comparison).
bool within(glm::vec3 v, float limit) {
  return std::abs(v.x) <= limit && std::abs(v.y) <= limit && std::abs(v.z) <= limit;
}

}  // namespace

std::vector<unsigned char> encodeVpls(std::span<const Vpl> vpls) {
  std::vector<unsigned char> out(kVplHeaderBytes + kRecordBytes * vpls.size(), 0);
  for (std::size_t i = 0; i < sizeof kVplMagic; ++i)
    out[i] = static_cast<unsigned char>(kVplMagic[i]);
  storeU32(out, 8, kVplFormatVersion);
  storeU32(out, 12, static_cast<uint32_t>(vpls.size()));
  for (std::size_t i = 0; i < vpls.size(); ++i) {
    const std::size_t at = kVplHeaderBytes + kRecordBytes * i;
    for (int c = 0; c < 3; ++c) {
      storeF32(out, at + 4 * c, vpls[i].position[c]);
      storeF32(out, at + 12 + 4 * c, vpls[i].normal[c]);
      storeF32(out, at + 24 + 4 * c, vpls[i].flux[c]);
      storeF32(out, at + 36 + 4 * c, vpls[i].from[c]);
    }
    storeU32(out, at + 48, vpls[i].path);
  }
  return out;
}

std::vector<Vpl> decodeVpls(const std::filesystem::path& file,
                            std::span<const unsigned char> bytes) {
  if (bytes.size() < kVplHeaderBytes)
    throw LoadError(file, "truncated: " + std::to_string(bytes.size()) +
                              " bytes, the header needs " + std::to_string(kVplHeaderBytes));
  if (std::memcmp(bytes.data(), kVplMagic, sizeof kVplMagic) != 0)
    throw LoadError(file, "bad magic: not a bounce VPL file");
  const uint32_t version = loadU32(bytes, 8);
  if (version != kVplFormatVersion)
    throw LoadError(file, "format version " + std::to_string(version) +
                              ", this build reads version " + std::to_string(kVplFormatVersion) +
                              ": rebake");
  const uint64_t count = loadU32(bytes, 12);
  const uint64_t expected = kVplHeaderBytes + kRecordBytes * count;
  if (bytes.size() != expected)
    throw LoadError(file, std::to_string(count) + " VPLs announced need " +
                              std::to_string(expected) + " bytes, the file has " +
                              std::to_string(bytes.size()));
  std::vector<Vpl> vpls(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = kVplHeaderBytes + kRecordBytes * i;
    Vpl& v = vpls[i];
    for (int c = 0; c < 3; ++c) {
      v.position[c] = loadF32(bytes, at + 4 * c);
      v.normal[c] = loadF32(bytes, at + 12 + 4 * c);
      v.flux[c] = loadF32(bytes, at + 24 + 4 * c);
      v.from[c] = loadF32(bytes, at + 36 + 4 * c);
    }
    v.path = loadU32(bytes, at + 48);
    const std::string which = "VPL " + std::to_string(i) + ": ";
    if (!within(v.position, kMaxBakeLength))
      throw LoadError(
          file, which + "position is not finite or beyond " + shortNumber(kMaxBakeLength) + " m");
    if (!finite(v.normal) || std::abs(glm::length(v.normal) - 1.0f) > 1e-3f)
      throw LoadError(file, which + "normal is not a unit vector");
    if (!(finite(v.flux) && v.flux.r >= 0.0f && v.flux.g >= 0.0f && v.flux.b >= 0.0f))
      throw LoadError(file, which + "flux is negative or not finite");
    if (!(v.flux.r <= kMaxVplFlux && v.flux.g <= kMaxVplFlux && v.flux.b <= kMaxVplFlux))
      throw LoadError(file, which + "flux is over " + shortNumber(kMaxVplFlux) + " W");
    if (!within(v.from, kMaxBakeLength))
      throw LoadError(file, which + "path segment start is not finite or beyond " +
                                shortNumber(kMaxBakeLength) + " m");
    if (i > 0 && v.path < vpls[i - 1].path)
      throw LoadError(file, which + "path index " + std::to_string(v.path) +
                                " is smaller than the previous VPL's " +
                                std::to_string(vpls[i - 1].path) +
                                " (a path's VPLs must be consecutive, paths in order)");
  }
  return vpls;
}

void writeVplFile(const std::filesystem::path& file, std::span<const Vpl> vpls) {
  writeFileAtomically(file, encodeVpls(vpls));
}

std::vector<Vpl> readVplFile(const std::filesystem::path& file) {
  return decodeVpls(file, readBakeInputFile(file));
}

}  // namespace bounce
