// The MPI TileExchange (bake/tile_exchange.h) of `mpirun -np N bounce-bake SCENE -o DIR --mpi`:
// rank 0 is the keeper. It holds each stage's queue of tiles, costliest first, and computes
// from it like any rank; a thread of its own answers the other ranks, which ask for one tile
// at a time and send each back when done, so a fast rank takes more. Rank 0 journals every
// tile (its own and those it receives), so a run that dies resumes with --resume.
//
// Messages on MPI_COMM_WORLD (all little-endian bytes):
//   ask (rank k → 0):     u32 stage
//   tile (0 → rank k):    i64 tile, −1: the stage has no more
//   result (rank k → 0):  u32 stage | u32 tile | the tile's payload (bake/tile_payload.h)
//   done (rank k → 0):    nothing: rank k has finished its stages
// While the bake runs, only the answering thread calls MPI on rank 0, and one thread at a time
// on the others (MPI_THREAD_SERIALIZED).
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "bake/tile_exchange.h"

namespace bounce {

// MPI_Init_thread on construction, MPI_Finalize on destruction. Throws std::runtime_error when
// MPI cannot give MPI_THREAD_SERIALIZED.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank of the run with `code` (after an error on one of them).
  [[noreturn]] static void abortAll(int code);

 private:
  int rank_ = 0, size_ = 1;
};

class MpiTileExchange final : public TileExchange {
 public:
  explicit MpiTileExchange(const MpiSession& session);
  // The keeper waits for every other rank's "done"; the others send theirs.
  ~MpiTileExchange() override;

  bool keeper() const override { return rank_ == 0; }
  void open(TileStage stage, std::vector<uint32_t> tiles) override;
  std::optional<uint32_t> next(TileStage stage) override;
  void finished(const TileRecord& record) override;
  std::vector<TileRecord> gather(TileStage stage) override;
  // The keeper: tiles (of every stage) each rank computed, rank 0 first.
  std::vector<int> tilesByRank() const;

 private:
  void answer();                            // the keeper's answering thread
  bool serveAsk(int rank, uint32_t stage);  // false: hold the ask until `stage` opens

  int rank_, size_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  uint32_t openStage_ = 0;  // the stage whose queue is open (0: none yet)
  std::deque<uint32_t> queue_;
  int outstanding_ = 0;  // tiles handed to other ranks and not yet back
  std::vector<TileRecord> received_;
  std::vector<int> tilesByRank_;
  std::thread answering_;
};

}  // namespace bounce
