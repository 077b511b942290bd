// A sweep shared out over the tasks of a job array (SLURM's `--array`, or --array-task and
// --array-count): task I of M runs every M-th point from the I-th, so that each task gets points
// from all over the sweep (neighbouring points often cost alike); results.csv is gathered once all
// of them ended (`granule sweep DIR --collect`).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace granule::sweep {

struct ArrayShare {
  int task = 0;
  int count = 1;
  // The indices of this task's points among `total`.
  std::vector<std::size_t> points(std::size_t total) const;
};

// The task and count given, else SLURM's array variables (task IDs counted from
// SLURM_ARRAY_TASK_MIN, so that `--array=1-8` works as well as `--array=0-7`) unless the sweep
// runs over MPI; none when neither.  Throws BadSweepInput for one of task and count without the
// other, a task outside [0, count), or a variable that is not a task number.
std::optional<ArrayShare> array_share(std::optional<int> task, std::optional<int> count, bool mpi);

}  // namespace granule::sweep
