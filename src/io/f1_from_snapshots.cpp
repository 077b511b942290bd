#include "io/f1_from_snapshots.hpp"

namespace granule {

using namespace granule::distribution;

std::vector<WindowSamples> sample_snapshot_windows(const std::string& snapshots, const SnapshotRead& first,
                                                   std::int64_t from_frame, const SamplingOptions& sampling,
                                                   const std::vector<ValueWindow>& densities,
                                                   const std::vector<ValueWindow>& temperatures) {
  std::vector<WindowSamples> windows;
  for (const ValueWindow& rho : densities) {
    for (const ValueWindow& t : temperatures) windows.push_back(WindowSamples{rho, t, {}, {}, {}, {}, {}});
  }
  const SystemParams& system = first.metadata.system;
  const ShearFrame frame{system.length_x, system.length_y, system.shear_velocity};
  for (std::int64_t index = from_frame; index < first.frames; ++index) {
    const SnapshotRead snapshot = index == 0 ? first : read_snapshot(snapshots, index);
    sample_configuration(snapshot.frame.particles, frame, sampling, windows);
  }
  return windows;
}

}  // namespace granule
