#include "bake_mpi.h"

#include <cstdio>
#include <filesystem>
#include <string>

#include "bake_progress_line.h"
#include "mpi/mpi_tile_exchange.h"
#include "pipeline/scene_bake.h"
#include "scene/scene.h"

namespace bounce {

int bakeOverMpi(const Scene& scene, SceneBakeSettings settings, const BakeOutput& out,
                bool drawProgress) {
  MpiSession session;
  const int rank = session.rank();
  try {
    MpiTileExchange exchange(session);
    settings.exchange = &exchange;
    if (rank != 0) {  // a worker: its tiles go to rank 0, nothing is written here
      settings.journal.clear();
      settings.resume = false;
      bakeScene(scene, settings, nullptr);
      return 0;
    }
    listenForInterrupt();
    ProgressLineObserver observer(drawProgress);
    SceneBake baked = bakeScene(scene, settings, &observer);
    std::string shares;
    const std::vector<int> tiles = exchange.tilesByRank();
    for (std::size_t r = 0; r < tiles.size(); ++r)
      shares += (r ? ", " : "") + std::to_string(tiles[r]);
    baked.notes.push_back("baked over " + std::to_string(session.size()) +
                          " MPI ranks; tiles computed by rank 0, 1, ...: " + shares);
    writeBakeAndReport(baked, out);
    if (!settings.journal.empty()) std::filesystem::remove(settings.journal);
    return 0;
  } catch (const BakeCancelled&) {
    std::fprintf(stderr, "\nbounce-bake: cancelled on rank 0: nothing written (%s is as it was)\n",
                 out.folder.string().c_str());
    MpiSession::abortAll(130);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bounce-bake: error on MPI rank %d of %d: %s\n", rank, session.size(),
                 e.what());
    MpiSession::abortAll(1);
  }
}

}  // namespace bounce
