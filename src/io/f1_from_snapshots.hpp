// Steps (1)–(3) of the cumulative sampling of thesis §5.2 over a run's snapshot file (`granule
// analyze f1`): every pair of a density and a temperature window sampled in every frame from
// `from_frame` on (distribution/window_sampling.hpp), ready for distribution::analyse_window.
#pragma once

#include <cstdint>
#include <vector>

#include "distribution/window_sampling.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

// `first` is frame 0 of the file `snapshots`; the windows come density by density, each with every
// temperature window.
std::vector<distribution::WindowSamples> sample_snapshot_windows(const std::string& snapshots, const SnapshotRead& first,
                                                                 std::int64_t from_frame,
                                                                 const distribution::SamplingOptions& sampling,
                                                                 const std::vector<distribution::ValueWindow>& densities,
                                                                 const std::vector<distribution::ValueWindow>& temperatures);

}  // namespace granule
