// Sweep points shared out over MPI ranks (`mpirun -n K granule sweep SPEC --out DIR --mpi`):
// rank 0 hands out one point at a time to whichever rank asks next, so long and short runs
// balance; ranks 1 … K−1 run them as child processes (point_runs.hpp) and report back.  The
// ranks share DIR (one file system); each point's record is written by the rank that ran it.
// Built only when CMake found MPI (GRANULE_HAVE_MPI).
#pragma once

#include "sweep/point_runs.hpp"

namespace granule::sweep {

struct MpiWorld {
  int rank = 0;
  int size = 1;
};

// MPI_Init on construction, MPI_Finalize on destruction.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  const MpiWorld& world() const { return world_; }

  // Rank 0's `value` on every rank.
  int broadcast(int value) const;

 private:
  MpiWorld world_;
};

// Runs every point of the spec over the ranks (rank 0 prints one line per point as it ends).
// With a single rank, that rank runs them itself, one at a time.
void run_points_over_mpi(const SweepRun& run, const MpiWorld& world);

}  // namespace granule::sweep
