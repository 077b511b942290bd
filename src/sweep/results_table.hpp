// DIR/results.csv: one row per point — the point's name, its swept values, how it ended (status,
// exit code, error, wall seconds of the last attempt) and every scalar of its summary.json
// (nested objects flattened with dots, list items by index: steady_shear.temperature_measured,
// box.1).
#pragma once

#include <string>

#include "sweep/sweep_directory.hpp"

namespace granule::sweep {

// How many points ended how, over the whole sweep.
struct SweepTally {
  int finished = 0, collapsed = 0, failed = 0, interrupted = 0, pending = 0;
  void add(const std::string& status);
  bool complete() const { return failed == 0 && interrupted == 0 && pending == 0; }
};

// Writes results.csv from the points' records and summaries as they are now; returns the tally.
SweepTally write_results(const SweepDirectory& dir, const SweepSpec& spec);

// "8 points: 7 finished, 1 failed; results in DIR/results.csv"
std::string tally_line(const SweepTally& tally, const SweepDirectory& dir);

}  // namespace granule::sweep
