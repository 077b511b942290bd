// The coarse-grained fields of §1.4.3 computed from a run's saved snapshots (`granule analyze
// fields`): per frame the instantaneous fields, and the running average over the frames from the
// first (the last frame holds the average over all of them), written as a fields file.  The
// collisional stress needs the collisions themselves and is measured only during a run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/field_grid.hpp"
#include "io/io_error.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

struct FieldsFromSnapshots {
  std::string snapshots;              // the snapshot file
  SnapshotMetadata metadata;          // its metadata (frame 0's read)
  std::int64_t first = 0, last = 0;   // frames first..last, indices ≥ 0
  FieldGrid grid;
  bool subtract_shear = false;        // velocities relative to u(y) = γ (y − L_y/2) before averaging
  std::string out;                    // the fields file written (atomically)
  std::string version;                // of the program, recorded in the file
};

// The grid of the fields: about 20 particles per cell (analysis/field_grid.hpp), or `cells` NX NY
// (NZ in 3D), each in [1, 16384]; other cells throw InputError.
FieldGrid fields_from_snapshots_grid(const SystemParams& system, const std::vector<int>& cells);

void write_fields_from_snapshots(const FieldsFromSnapshots& request);

}  // namespace granule
