// The runs of `granule reproduce`'s studies as sweeps: one sweep directory per run group under
// DIR/runs/<study>/<group>, so that a second call skips what finished, and what the points of a
// group left behind (records, time series, summaries), read back for the study's claims.
#pragma once

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "reproduce/run_outputs.hpp"
#include "reproduce/study.hpp"
#include "sweep/sweep_directory.hpp"
#include "sweep/sweep_spec.hpp"
#ifdef GRANULE_HAVE_MPI
#include "sweep/mpi_points.hpp"
#endif

namespace granule::reproduce {

// One run group of a study: its sweep spec and directory.
struct GroupRun {
  const Study* study;
  std::string group;
  sweep::SweepSpec spec;
  sweep::SweepDirectory dir;
};

// Every run group of `studies` at `scale`, their directories under `out`/runs.  A catalogue spec
// that does not parse is a bug of the study (std::logic_error), not the user's input.
std::vector<GroupRun> planned_groups(const std::vector<const Study*>& studies, Scale scale,
                                     const std::filesystem::path& out);

// Runs every group's points, skipping those that finished: `jobs` at a time on this machine as
// child processes of the executable `granule` (`announce`: one line per group first).  False when
// a signal (`*interrupt` non-zero) stopped it.
bool run_groups_locally(const std::vector<GroupRun>& groups, int jobs, const std::string& granule,
                        const volatile std::sig_atomic_t* interrupt);

#ifdef GRANULE_HAVE_MPI
// The same over the ranks of `mpi` (sweep/mpi_points.hpp): rank 0 prepares the directories and
// hands out the points, and every rank ends a group before any starts the next.
bool run_groups_over_mpi(const std::vector<GroupRun>& groups, const sweep::MpiSession& mpi, const std::string& granule,
                         const volatile std::sig_atomic_t* interrupt);
#endif

struct GroupReading {
  GroupOutputs outputs;
  std::string tally_line;    // how the group's runs ended ("chapter2/system_I: 2 points: 2 finished")
  bool complete = true;      // every point finished
  double run_seconds = 0.0;  // the points' own wall times, summed (their last attempts)
};

// Writes the group's results.csv and reads every point's record, time series and summary.json.
GroupReading read_group(const GroupRun& g);

}  // namespace granule::reproduce
