// The journal of a bake's finished tiles: a file beside the output that grows by one record per
// tile as the irradiance and visibility stages finish them (tile_payload.h), so a killed bake
// resumes where it stopped (bounce-bake --resume) and shards hand their tiles to a merge.
//
// File, little-endian:
//   char[8] "BNCTILES" | u32 journal version | u32 n | n bytes of key (JSON text) | u64 FNV-1a
//   of the key, then records:
//   u32 "TILE" | u32 stage | u32 tile | u32 payload bytes | payload | u64 FNV-1a of the 16 bytes
//   before the payload and the payload.
// The key says what the tiles depend on (scene hash, settings, ray kernel, atlas size, tile
// size, bounce's formats: pipeline/scene_bake.cpp); a journal whose key differs is refused, naming
// what differs. The header is written whole before the first record (to a temporary file, then
// renamed). A kill can cut the last record short: reading stops at the first record that is cut
// or fails its check, and the next append overwrites it. Each record goes out in one write(),
// so a kill -9 (which leaves the page cache to the kernel) loses at most the record in flight.
#pragma once

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/tile_record.h"

namespace bounce {

// 2: the key's settings are bake_folder/bake_settings.h's (bake.json's names: maxSpp, not spp).
// 3: an irradiance texel carries its half-sample difference and its first samples' mean
// (tile_payload.h, 44 bytes).
inline constexpr uint32_t kTileJournalVersion = 3;

struct TileJournal {
  nlohmann::json key;
  std::vector<TileRecord> records;  // whole ones, in file order
  uint64_t validBytes = 0;          // header and whole records
  uint64_t droppedBytes = 0;        // after them: a record cut by a kill, or damage
};

// Throws LoadError naming the file when it is not a journal (bad magic, version, header check).
TileJournal readTileJournal(const std::filesystem::path& file);
// Its key only (the header), checked as above.
nlohmann::json readTileJournalKey(const std::filesystem::path& file);

// Throws LoadError(file, ...) naming the first key field that differs from `expected`, but for
// the fields named in `ignored`.
void checkTileJournalKey(const std::filesystem::path& file, const nlohmann::json& found,
                         const nlohmann::json& expected, std::span<const char* const> ignored = {});

// Appends records; thread-safe.
class TileJournalWriter {
 public:
  // Starts `file` afresh with `key` (replacing any file there).
  TileJournalWriter(const std::filesystem::path& file, const nlohmann::json& key);
  // Goes on with `file` as read: keeps its first `journal.validBytes` bytes, appends after.
  TileJournalWriter(const std::filesystem::path& file, const TileJournal& journal);
  ~TileJournalWriter();
  TileJournalWriter(const TileJournalWriter&) = delete;
  TileJournalWriter& operator=(const TileJournalWriter&) = delete;

  // Throws std::runtime_error naming the file when the write fails (a full disk).
  void append(const TileRecord& record);
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  int fd_ = -1;
  std::mutex mutex_;
};

}  // namespace bounce
