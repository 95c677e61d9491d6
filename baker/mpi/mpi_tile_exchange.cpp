#include "mpi/mpi_tile_exchange.h"

#include "io/byte_stream.h"

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace bounce {
namespace {

constexpr int kAsk = 1, kTile = 2, kResult = 3, kDone = 4;

}  // namespace

MpiSession::MpiSession() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  if (provided < MPI_THREAD_SERIALIZED) {
    MPI_Finalize();
    throw std::runtime_error(
        "this MPI does not allow calls from more than one thread "
        "(MPI_THREAD_SERIALIZED), which --mpi needs");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

void MpiSession::abortAll(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return
}

MpiTileExchange::MpiTileExchange(const MpiSession& session)
    : rank_(session.rank()), size_(session.size()), tilesByRank_(session.size(), 0) {
  if (keeper() && size_ > 1) answering_ = std::thread([this] { answer(); });
}

MpiTileExchange::~MpiTileExchange() {
  if (keeper()) {
    if (answering_.joinable()) answering_.join();
  } else {
    const std::lock_guard<std::mutex> lock(mutex_);
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kDone, MPI_COMM_WORLD);
  }
}

void MpiTileExchange::open(TileStage stage, std::vector<uint32_t> tiles) {
  if (!keeper()) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  openStage_ = static_cast<uint32_t>(stage);
  queue_.assign(tiles.begin(), tiles.end());
  received_.clear();
  changed_.notify_all();
}

std::optional<uint32_t> MpiTileExchange::next(TileStage stage) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (keeper()) {
    if (queue_.empty()) return std::nullopt;
    const uint32_t tile = queue_.front();
    queue_.pop_front();
    ++tilesByRank_[0];
    return tile;
  }
  const uint32_t ask = static_cast<uint32_t>(stage);
  MPI_Send(&ask, 1, MPI_UINT32_T, 0, kAsk, MPI_COMM_WORLD);
  int64_t tile = -1;
  MPI_Recv(&tile, 1, MPI_INT64_T, 0, kTile, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (tile < 0) return std::nullopt;
  return static_cast<uint32_t>(tile);
}

void MpiTileExchange::finished(const TileRecord& record) {
  if (keeper()) return;  // the keeper's own tiles are journalled where they are made
  ByteWriter message;
  message.u32(static_cast<uint32_t>(record.stage));
  message.u32(record.tile);
  message.raw(record.bytes.data(), record.bytes.size());
  const std::lock_guard<std::mutex> lock(mutex_);
  MPI_Send(message.bytes().data(), static_cast<int>(message.bytes().size()), MPI_BYTE, 0, kResult,
           MPI_COMM_WORLD);
}

std::vector<TileRecord> MpiTileExchange::gather(TileStage stage) {
  if (!keeper()) return {};
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return queue_.empty() && outstanding_ == 0; });
  std::vector<TileRecord> records = std::move(received_);
  received_.clear();
  for (const TileRecord& r : records)
    if (r.stage != stage)
      throw std::runtime_error("rank sent a tile of another stage (a bug: please report)");
  return records;
}

std::vector<int> MpiTileExchange::tilesByRank() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return tilesByRank_;
}

bool MpiTileExchange::serveAsk(int rank, uint32_t stage) {
  int64_t tile = -1;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stage > openStage_) return false;  // the keeper has not reached it yet
    if (stage == openStage_ && !queue_.empty()) {
      tile = queue_.front();
      queue_.pop_front();
      ++outstanding_;
    }
  }
  MPI_Send(&tile, 1, MPI_INT64_T, rank, kTile, MPI_COMM_WORLD);
  return true;
}

void MpiTileExchange::answer() {
  std::vector<std::pair<int, uint32_t>> held;  // asks for a stage not open yet
  int done = 0;
  while (done < size_ - 1) {
    for (std::size_t i = 0; i < held.size();)
      if (serveAsk(held[i].first, held[i].second))
        held.erase(held.begin() + static_cast<std::ptrdiff_t>(i));
      else
        ++i;
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) {
      std::this_thread::sleep_for(std::chrono::microseconds(500));
      continue;
    }
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    std::vector<unsigned char> message(static_cast<std::size_t>(bytes));
    MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (status.MPI_TAG == kAsk && bytes == 4) {
      const uint32_t stage = ByteReader("MPI", message).u32("the stage");
      if (!serveAsk(status.MPI_SOURCE, stage)) held.emplace_back(status.MPI_SOURCE, stage);
    } else if (status.MPI_TAG == kResult && bytes >= 8) {
      ByteReader head("MPI", message);
      TileRecord record;
      record.stage = static_cast<TileStage>(head.u32("the stage"));
      record.tile = head.u32("the tile");
      record.bytes.assign(message.begin() + 8, message.end());
      record.source = "MPI rank " + std::to_string(status.MPI_SOURCE);
      const std::lock_guard<std::mutex> lock(mutex_);
      received_.push_back(std::move(record));
      --outstanding_;
      ++tilesByRank_[static_cast<std::size_t>(status.MPI_SOURCE)];
      changed_.notify_all();
    } else if (status.MPI_TAG == kDone) {
      ++done;
    }
  }
}

}  // namespace bounce
