// One finished tile of one tiled stage, as its bytes (tile_payload.h holds the stages' codecs):
// what the journal holds (pipeline/tile_journal.h), what shards and MPI ranks hand back
// (tile_exchange.h), and what the tile scheduler (tile_scheduler.h) restores.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace bounce {

// 64 × 64 texels, GPU Lightmass's tile: a tile of the Conference Room's covered texels takes a
// few seconds on one core, and its journal record is at most 64² × 44 bytes.
inline constexpr int kDefaultTileSize = 64;

// The tiled stages (values as journalled).
enum class TileStage : uint32_t { Irradiance = 1, Visibility = 2 };

// "irradiance", "visibility": for messages.
inline const char* tileStageName(TileStage stage) {
  return stage == TileStage::Irradiance ? "irradiance" : "visibility";
}

struct TileRecord {
  TileStage stage = TileStage::Irradiance;
  uint32_t tile = 0;
  std::vector<unsigned char> bytes;
  std::filesystem::path source;  // the journal it was read from (for errors); empty when new
};

}  // namespace bounce
