// Tiles shared out among processes while they bake (bounce-bake --mpi): one process, the
// keeper, holds the queue of each texel stage's tiles, hands them out one at a time to whoever
// asks first (itself included), gathers what the others computed and writes the folder; the
// others compute what they are handed and stop after the tile stages. Every process runs the
// same stages before the tiles (atlas, coverage, leak guard), so all agree on the tiles and on
// each tile's texels. GL-free and MPI-free: mpi/mpi_tile_exchange.h is the MPI one.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bake/tile_record.h"

namespace bounce {

class TileExchange {
 public:
  virtual ~TileExchange() = default;
  // True in the process that gathers the tiles and finishes the bake.
  virtual bool keeper() const = 0;
  // The keeper opens each stage with the tiles to hand out, costliest first (those a journal
  // restored already taken off); the others' call is ignored.
  virtual void open(TileStage stage, std::vector<uint32_t> tiles) = 0;
  // The next tile of `stage` for this process to compute; none once the stage's queue is empty.
  virtual std::optional<uint32_t> next(TileStage stage) = 0;
  // A tile this process computed (the others send it to the keeper).
  virtual void finished(const TileRecord& record) = 0;
  // The keeper: waits until every tile of `stage` handed to others has come back and returns
  // them. The others: nothing.
  virtual std::vector<TileRecord> gather(TileStage stage) = 0;
};

}  // namespace bounce
