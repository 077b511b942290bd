// `granule analyze f1`: the single-particle velocity distribution by cumulative sampling
// (thesis Chapter 5, Appendix B).  The command lives in analyze_f1.cpp; its output files
// (schema in docs/f1.md) are written by analyze_f1_output.cpp.
#pragma once

#include <string>
#include <vector>

#include "distribution/f1_analysis.hpp"
#include "io/snapshot_file.hpp"

namespace granule::app {

struct F1RunDescription {
  std::string source;
  SnapshotMetadata metadata;
  int cells_x = 1, cells_y = 1;
  std::int64_t from_frame = 0, frames_used = 0;
  bool subtract_shear_profile = false;
  double profile_angle = 0.0;   // θ of the f(v) profiles (Fig 5.10)
  double profile_speed = 0.0;   // v of the f(θ) profiles (Fig 5.11); 0: √(2T) of each window
  distribution::F1Options options;
};

// Writes `out` (HDF5) and the CSV tables beside it (<stem>_table.csv, _windows.csv, _speed.csv,
// _cumulative.csv, _angular.csv, _profiles.csv), each atomically.  Returns the paths written.
std::vector<std::string> write_f1_outputs(const std::string& out, const F1RunDescription& run,
                                          const std::vector<distribution::WindowResult>& windows);

}  // namespace granule::app
