// Output files of `granule analyze f1` (format "granule-f1", schema in docs/f1.md): one HDF5 file
// with a group per window, and CSV tables beside it: the Appendix B table, a per-window summary
// (Figs 5.5–5.9), and the curves behind Figs 5.1–5.4, 5.10 and 5.11.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "distribution/f1_analysis.hpp"
#include "io/file_schema.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

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

// What f1.h5 holds (io/file_schema.hpp), checked before a figure script reads it.
const h5::FileSchema& f1_schema();

// Writes `out` (HDF5) and the CSV tables beside it (<stem>_table.csv, _windows.csv, _speed.csv,
// _cumulative.csv, _angular.csv, _profiles.csv), each atomically, and <stem>_thesis.csv with
// `thesis_comparison` (the comparison with Appendix B) unless that is empty.  Returns the paths
// written.
std::vector<std::string> write_f1_outputs(const std::string& out, const F1RunDescription& run,
                                          const std::vector<distribution::WindowResult>& windows,
                                          const std::string& thesis_comparison);

}  // namespace granule
