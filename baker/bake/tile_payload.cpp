#include "bake/tile_payload.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bake/light_visibility_bake.h"
#include "bake/texel_coverage.h"
#include "bake/texel_irradiance.h"

#include "io/byte_stream.h"

namespace bounce {
namespace {

constexpr std::size_t kIrradianceTexelBytes = 44;
constexpr std::size_t kVisibilityTexelBytes = 2 * kVisibilitySlots + 4 * kVisibilitySlots + 20;

// Calls f(texel) for the tile's covered texels in the payload's order.
template <class F>
void forCoveredTexels(const TexelCoverage& coverage, TileRect tile, F f) {
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const std::size_t t = static_cast<std::size_t>(y) * coverage.width + x;
      if (coverage.covered(t)) f(t);
    }
}

std::size_t coveredIn(const TexelCoverage& coverage, TileRect tile) {
  std::size_t n = 0;
  forCoveredTexels(coverage, tile, [&](std::size_t) { ++n; });
  return n;
}

void checkSize(const std::filesystem::path& source, std::size_t bytes, std::size_t texels,
               std::size_t perTexel, const char* what) {
  if (bytes != texels * perTexel)
    throw LoadError(source, std::string("a ") + what + " tile of " + std::to_string(bytes) +
                                " bytes, where its " + std::to_string(texels) +
                                " covered texels take " + std::to_string(texels * perTexel) +
                                ": it was made for another atlas or coverage");
}

}  // namespace

std::vector<unsigned char> encodeIrradianceTile(const TexelIrradiance& from,
                                                const TexelCoverage& coverage, TileRect tile) {
  ByteWriter w;
  forCoveredTexels(coverage, tile, [&](std::size_t t) {
    const glm::vec3 e = from.irradiance.pixels[t];
    w.f32(e.r), w.f32(e.g), w.f32(e.b);
    w.u32(from.samples[t]);
    w.f32(from.relativeError[t]);
    w.u32(from.nonFinite[t]);
    w.u32(from.rays[t]);
    const glm::vec3 d = from.halfDifference.pixels[t];
    w.f32(d.r), w.f32(d.g), w.f32(d.b);
    w.f32(from.prefixLuminance[t]);
  });
  return w.take();
}

void decodeIrradianceTile(const std::filesystem::path& source, std::span<const unsigned char> bytes,
                          const TexelCoverage& coverage, TileRect tile, TexelIrradiance& into) {
  checkSize(source, bytes.size(), coveredIn(coverage, tile), kIrradianceTexelBytes, "irradiance");
  ByteReader r(source, bytes);
  forCoveredTexels(coverage, tile, [&](std::size_t t) {
    glm::vec3& e = into.irradiance.pixels[t];
    e.r = r.f32("E"), e.g = r.f32("E"), e.b = r.f32("E");
    into.samples[t] = r.u32("samples");
    into.relativeError[t] = r.f32("the relative error");
    into.nonFinite[t] = r.u32("the non-finite count");
    into.rays[t] = r.u32("the ray count");
    glm::vec3& d = into.halfDifference.pixels[t];
    d.r = r.f32("D"), d.g = r.f32("D"), d.b = r.f32("D");
    into.prefixLuminance[t] = r.f32("the first samples' mean");
    if (!std::isfinite(d.r + d.g + d.b) || !(into.prefixLuminance[t] >= 0.0f))
      throw LoadError(source,
                      "texel " + std::to_string(t) +
                          " holds a non-finite half-sample difference or a negative mean of "
                          "its first samples: a bake never writes that");
    const float largest = std::max(e.r, std::max(e.g, e.b)),
                smallest = std::min(e.r, std::min(e.g, e.b));
    if (!(smallest >= 0.0f && std::isfinite(largest)) || !(into.relativeError[t] >= 0.0f))
      throw LoadError(source, "texel " + std::to_string(t) + " holds E = (" + std::to_string(e.r) +
                                  ", " + std::to_string(e.g) + ", " + std::to_string(e.b) +
                                  ") W/m²: a bake never writes that");
  });
}

std::vector<unsigned char> encodeVisibilityTile(const VisibilityTexels& from,
                                                const TexelCoverage& coverage, TileRect tile) {
  ByteWriter w;
  forCoveredTexels(coverage, tile, [&](std::size_t t) {
    const TexelVisibility& record = from.map.texels[t];
    for (const uint16_t light : record.light) w.u16(light);
    for (const float v : record.visible) w.f32(v);
    w.f64(from.irradiance[t]);
    w.f64(from.otherIrradiance[t]);
    w.u32(from.rays[t]);
  });
  return w.take();
}

void decodeVisibilityTile(const std::filesystem::path& source, std::span<const unsigned char> bytes,
                          const TexelCoverage& coverage, TileRect tile, VisibilityTexels& into) {
  checkSize(source, bytes.size(), coveredIn(coverage, tile), kVisibilityTexelBytes, "visibility");
  ByteReader r(source, bytes);
  forCoveredTexels(coverage, tile, [&](std::size_t t) {
    TexelVisibility& record = into.map.texels[t];
    for (uint16_t& light : record.light) light = r.u16("a light");
    for (float& v : record.visible) v = r.f32("a visible fraction");
    into.irradiance[t] = r.f64("the irradiance");
    into.otherIrradiance[t] = r.f64("the other lights' irradiance");
    into.rays[t] = r.u32("the ray count");
    for (int s = 0; s < kVisibilitySlots; ++s)
      if ((record.light[s] >= into.map.indexCount() && record.light[s] != kNoLight &&
           record.light[s] != kOtherLights) ||
          !(record.visible[s] >= 0.0f && record.visible[s] <= 1.0f))
        throw LoadError(
            source,
            "texel " + std::to_string(t) + " names light " + std::to_string(record.light[s]) +
                " with V = " + std::to_string(record.visible[s]) + ": the scene has " +
                std::to_string(into.map.lightCount) + " static area lights and " +
                std::to_string(into.map.punctualCount) + " punctual ones, and V lies in [0, 1]");
  });
}

}  // namespace bounce
