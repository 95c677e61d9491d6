// A finished tile's texels as bytes: what the journal (tile_journal.h) holds per tile and stage,
// and what shards and MPI ranks hand back. Only covered texels (sample points after the leak
// guard) are stored, rows top first, left to right; the reader knows which from the coverage.
// All values little-endian, bit for bit as computed, so a restored tile equals a recomputed one.
//
//   irradiance, 44 bytes a texel:  f32 E.r, E.g, E.b (W/m²) | u32 samples | f32 relative error |
//                                  u32 non-finite samples | u32 rays | f32 D.r, D.g, D.b (W/m²,
//                                  the half-sample difference) | f32 the first samples' mean
//                                  luminance (W/m²; both delivered_error.h)
//   visibility, 44 bytes a texel:  4 × u16 light | 4 × f32 V | f64 Σ unshadowed E (W/m²,
//                                  luminance) | f64 its kOtherLights part | u32 rays
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "bake/tile_grid.h"
#include "bake/tile_record.h"

namespace bounce {

struct TexelCoverage;
struct TexelIrradiance;
struct VisibilityTexels;

std::vector<unsigned char> encodeIrradianceTile(const TexelIrradiance& from,
                                                const TexelCoverage& coverage, TileRect tile);
std::vector<unsigned char> encodeVisibilityTile(const VisibilityTexels& from,
                                                const TexelCoverage& coverage, TileRect tile);

// Write the tile's texels into `into` (sized for the whole atlas). Throw LoadError(source, ...)
// when the bytes do not fit the tile's covered texels (a journal of another coverage).
void decodeIrradianceTile(const std::filesystem::path& source, std::span<const unsigned char> bytes,
                          const TexelCoverage& coverage, TileRect tile, TexelIrradiance& into);
void decodeVisibilityTile(const std::filesystem::path& source, std::span<const unsigned char> bytes,
                          const TexelCoverage& coverage, TileRect tile, VisibilityTexels& into);

}  // namespace bounce
