// How a sweep point ended, kept in DIR/points/NAME.json beside its run directory so that a
// restart, another array task and --collect all know it without asking the run again.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sweep/sweep_directory.hpp"

namespace granule::sweep {

// "finished": the run ended as configured (exit 0); "collapsed": it stopped on inelastic collapse
// with its outputs written (exit 3, a physical result, not retried); "interrupted": a signal
// stopped it after writing its checkpoint (resumed next time); "failed": any other exit, or the
// run died (run again next time); "pending": never run.
struct PointRecord {
  std::string status = "pending";
  int exit_code = -1;
  std::string error;     // the run's own message, for failed points
  double seconds = 0.0;  // wall time of the last attempt
};

// The record of a `granule run` that exited with `wait_status` (waitpid's) after `seconds`; the
// error is taken from the run's log.
PointRecord record_of_exit(int wait_status, double seconds, const std::string& log_path);

// A finished run whose record is missing (the sweep stopped between the two): rebuilt from its
// summary.json (point_summary.hpp; its "stop_reason" and "wall_seconds" checked like a record).
std::optional<PointRecord> record_from_summary(const SweepDirectory& dir, const SweepPoint& point);

void write_record(const SweepDirectory& dir, const SweepPoint& point, const PointRecord& record);
// std::nullopt when the point has no record.  A record that is not what write_record writes (the
// point's name, a known status, an exit code in [0, 255], an error text, seconds finite and
// >= 0) is refused with an InputError naming the record and the key, and telling to delete it.
std::optional<PointRecord> read_record(const SweepDirectory& dir, const SweepPoint& point);

// What a point's record says, or its summary, or "pending".
PointRecord current_record(const SweepDirectory& dir, const SweepPoint& point);

// Reads the record and summary of each point of `indices`, so that a damaged one refuses the sweep
// (InputError) before any point starts.
void check_point_files(const SweepDirectory& dir, const SweepSpec& spec, const std::vector<std::size_t>& indices);

bool is_done(const PointRecord& record);  // finished or collapsed: a restart skips it

}  // namespace granule::sweep
