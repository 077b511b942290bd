// `granule analyze spins`: the spin correlation of neighbouring grains (analysis/spin_correlation.hpp,
// thesis Fig C.4) of the chosen frames of a run's snapshots, frame by frame into spins.h5
// (io/spins_file.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/spin_correlation.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

struct SpinsRequest {
  std::string snapshots;  // the run's snapshots.h5
  std::string out;        // spins.h5
  SpinCorrelationSettings settings;
};

// Reads `frames` (frame 0 is `first`), writes and publishes `request.out`, returns the average.  A
// run of smooth grains, settings out of range or a box too small for them throw InputError before
// anything is written.
SpinCorrelationAverage spins_from_snapshots(const SpinsRequest& request, const SnapshotRead& first,
                                            const std::vector<std::int64_t>& frames);

}  // namespace granule
