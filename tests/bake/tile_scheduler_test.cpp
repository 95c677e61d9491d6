// The tile scheduler (bake/tile_scheduler.h) with a stand-in stage whose texels say how each
// tile came: computed here, or decoded from a journal's bytes. It must restore what a journal
// holds instead of computing it, compute and journal every other tile of the bake's share once,
// and refuse a tile that is not the bake's or a merge that lacks one.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "bake/tile_scheduler.h"
#include "io/load_error.h"

namespace bounce {
namespace {

constexpr int kComputed = 1, kRestored = 2;

// The stand-in stage's whole map: per tile, how it came (0: not at all) and how many times.
struct Marks {
  std::vector<int> how, times;
};

TiledStage<Marks> markingStage(const TileGrid& grid) {
  TiledStage<Marks> stage;
  stage.stage = TileStage::Irradiance;
  stage.compute = [&grid](const TileWork& work, StageProgress*, auto done) {
    Marks marks{std::vector<int>(grid.count(), 0), std::vector<int>(grid.count(), 0)};
    for (const uint32_t tile : work.tiles) {
      marks.how[tile] = kComputed;
      ++marks.times[tile];
      done(tile, marks);
    }
    return marks;
  };
  stage.encode = [](const Marks&, TileRect tile) {
    return std::vector<unsigned char>{static_cast<unsigned char>(tile.x0),
                                      static_cast<unsigned char>(tile.y0)};
  };
  stage.decode = [](const TileRecord& record, TileRect, Marks& into) {
    into.how[record.tile] = kRestored;
    ++into.times[record.tile];
  };
  return stage;
}

const BeginTileStage kSilent = [](uint64_t) { return std::unique_ptr<StageProgress>(); };

TileRecord journalled(uint32_t tile) {
  return {TileStage::Irradiance, tile, {7}, "earlier.journal"};
}

TEST(TileScheduler, RestoresTheJournalledTilesAndComputesAndJournalsEveryOtherOnce) {
  const TileGrid grid(8, 8, 2);  // 16 tiles
  std::vector<uint32_t> withWork(12);
  std::iota(withWork.begin(), withWork.end(), 2u);  // tiles 0, 1, 14, 15 have no work
  LightmapTiles tiles;
  tiles.restored = {journalled(3), journalled(9)};
  std::vector<uint32_t> finished;
  tiles.finished = [&](const TileRecord& record) { finished.push_back(record.tile); };
  TileScheduler scheduler(grid, withWork, tiles);
  const Marks marks = scheduler.run(markingStage(grid), kSilent);
  for (uint32_t t = 0; t < grid.count(); ++t) {
    const bool work = t >= 2 && t < 14;
    EXPECT_EQ(marks.how[t], !work ? 0 : (t == 3 || t == 9) ? kRestored : kComputed) << t;
    EXPECT_EQ(marks.times[t], work ? 1 : 0) << t;
  }
  std::sort(finished.begin(), finished.end());
  EXPECT_EQ(finished, (std::vector<uint32_t>{2, 4, 5, 6, 7, 8, 10, 11, 12, 13}));
  EXPECT_EQ(scheduler.restored(TileStage::Irradiance), 2u);
  EXPECT_FALSE(scheduler.partial());
}

// Two shards compute disjoint shares that together are every tile with work; a merge (no
// computing) that lacks one shard's tiles is refused.
TEST(TileScheduler, ShardsShareTheTilesAndAMergeMissingOneIsRefused) {
  const TileGrid grid(8, 8, 2);
  std::vector<uint32_t> withWork(16);
  std::iota(withWork.begin(), withWork.end(), 0u);
  std::vector<int> times(grid.count(), 0);
  std::vector<TileRecord> parts;
  for (int k = 0; k < 2; ++k) {
    LightmapTiles tiles;
    tiles.shard = k;
    tiles.shards = 2;
    TileScheduler scheduler(grid, withWork, tiles);
    EXPECT_TRUE(scheduler.partial());
    const Marks marks = scheduler.run(markingStage(grid), kSilent);
    for (uint32_t t = 0; t < grid.count(); ++t) times[t] += marks.times[t];
    if (k == 0)
      for (uint32_t t = 0; t < grid.count(); ++t)
        if (marks.how[t] == kComputed) parts.push_back(journalled(t));
  }
  EXPECT_EQ(times, std::vector<int>(grid.count(), 1));
  LightmapTiles merge;
  merge.restored = parts;  // shard 1's part only
  merge.computeMissing = false;
  TileScheduler scheduler(grid, withWork, merge);
  EXPECT_THROW(scheduler.run(markingStage(grid), kSilent), MissingTiles);
}

TEST(TileScheduler, ATileThatIsNotTheBakesIsRefusedNamingItsJournal) {
  const TileGrid grid(8, 8, 2);
  LightmapTiles tiles;
  tiles.restored = {journalled(0)};  // tile 0 has no work in this bake
  try {
    TileScheduler scheduler(grid, {5, 6}, tiles);
    ADD_FAILURE() << "a tile of another bake was taken";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("earlier.journal"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("holds tile 0, which is not one of this bake's 2"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace bounce
