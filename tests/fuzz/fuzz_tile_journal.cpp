// libFuzzer target: the tile journal and shard-part reader (pipeline/tile_journal.h) and the tile
// payload decoders (bake/tile_payload.h) that --resume, merge and MPI's rank 0 run on what they
// read. Each record is decoded against a coverage with every texel covered, of the atlas and
// tile size the key names (clamped to 64 × 64 texels), as a resume would. Allowed outcomes:
// a journal whose whole records and dropped tail add up to the input's size, each record
// decoded or refused with a LoadError naming the file; or a LoadError for the file. Anything
// else aborts.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "bake/light_visibility_bake.h"
#include "bake/texel_coverage.h"
#include "bake/texel_irradiance.h"
#include "bake/tile_grid.h"
#include "bake/tile_payload.h"
#include "fuzz_input_file.h"
#include "io/load_error.h"
#include "pipeline/tile_journal.h"

namespace {

int keyInt(const nlohmann::json& key, const char* name, int low, int high) {
  const auto it = key.find(name);
  if (it == key.end() || !it->is_number_integer()) return low;
  return static_cast<int>(std::clamp<int64_t>(it->get<int64_t>(), low, high));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  using namespace bounce;
  const std::filesystem::path file = fuzz::writeInput(data, size, "input.journal");
  TileJournal journal;
  try {
    journal = readTileJournal(file);
  } catch (const LoadError& e) {
    if (e.file() != file) std::abort();
    return 0;
  }
  if (journal.validBytes + journal.droppedBytes != size) std::abort();
  TexelCoverage coverage;
  coverage.width = keyInt(journal.key, "atlasWidth", 1, 64);
  coverage.height = keyInt(journal.key, "atlasHeight", 1, 64);
  const TileGrid grid(coverage.width, coverage.height, keyInt(journal.key, "tileSize", 1, 64));
  coverage.points.resize(coverage.texelCount());
  coverage.first.resize(coverage.texelCount() + 1);
  for (std::size_t t = 0; t <= coverage.texelCount(); ++t)
    coverage.first[t] = static_cast<uint32_t>(t);
  TexelIrradiance irradiance;
  irradiance.irradiance = Image(coverage.width, coverage.height);
  irradiance.samples.assign(coverage.texelCount(), 0);
  irradiance.relativeError.assign(coverage.texelCount(), 0.0f);
  irradiance.nonFinite.assign(coverage.texelCount(), 0);
  irradiance.rays.assign(coverage.texelCount(), 0);
  VisibilityTexels visibility;
  visibility.map.width = coverage.width;
  visibility.map.height = coverage.height;
  visibility.map.lightCount = 4;
  visibility.map.texels.resize(coverage.texelCount());
  visibility.rays.assign(coverage.texelCount(), 0);
  visibility.irradiance.assign(coverage.texelCount(), 0.0);
  visibility.otherIrradiance.assign(coverage.texelCount(), 0.0);
  for (const TileRecord& record : journal.records) {
    if (record.tile >= grid.count()) continue;  // the bake refuses it before decoding
    try {
      if (record.stage == TileStage::Irradiance)
        decodeIrradianceTile(record.source, record.bytes, coverage, grid.rect(record.tile),
                             irradiance);
      else
        decodeVisibilityTile(record.source, record.bytes, coverage, grid.rect(record.tile),
                             visibility);
    } catch (const LoadError& e) {
      if (e.file() != file) std::abort();
    }
  }
  return 0;
}
