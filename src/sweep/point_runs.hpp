// Running sweep points: each point is one child `granule run` process (a fresh run, or
// `--resume` of an interrupted one), up to K at a time.  A child process, not a run inside this
// process, so that a crash, an out-of-memory kill or a collapse exit of one point ends that point
// only, and so that K points use K cores without threads in the engine.
#pragma once

#include <csignal>
#include <cstddef>
#include <string>
#include <vector>

#include "sweep/point_record.hpp"
#include "sweep/sweep_directory.hpp"
#include "sweep/sweep_spec.hpp"

namespace granule::sweep {

struct SweepRun {
  std::string granule;  // the granule executable the points run with
  SweepDirectory dir;
  const SweepSpec* spec = nullptr;
  // Non-zero once SIGINT or SIGTERM arrived (the signal): no new point starts.  The running points
  // are in the sweep's process group, so a Ctrl-C or a batch system's signal to the job reaches
  // them too and they write their checkpoints.  The sweep does not pass the signal on: a run that
  // got it twice (from the job and from the sweep) would take the second as "stop at once".
  // A signal to the sweep process alone lets the running points finish.
  const volatile std::sig_atomic_t* interrupt = nullptr;
};

// Runs the points `indices` of the spec, at most `jobs` at once, skipping those already done and
// resuming those interrupted.  Prints one line per point when it ends (`print_progress`) and
// writes its record.  Returns the records, in the order of `indices`.
std::vector<PointRecord> run_points(const SweepRun& run, const std::vector<std::size_t>& indices, int jobs,
                                    bool print_progress);

// "NAME: finished in 1.23 s" (or "failed (exit 2) in ...: the error", "skipped: finished before").
std::string progress_line(const SweepPoint& point, const PointRecord& record, bool skipped);

}  // namespace granule::sweep
