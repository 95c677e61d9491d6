// bounce-bake --mpi: one bake over every rank of `mpirun -np N` (mpi/mpi_tile_exchange.h). Rank
// 0 writes the folder; the others compute tiles. Built where MPI is found.
#pragma once

#include "bake_summary.h"

namespace bounce {

struct Scene;
struct SceneBakeSettings;

// Every rank calls it with the same scene and settings. Returns the exit code; an error on any
// rank ends every rank (MPI_Abort) with its message naming the rank.
int bakeOverMpi(const Scene& scene, SceneBakeSettings settings, const BakeOutput& out,
                bool drawProgress);

}  // namespace bounce
